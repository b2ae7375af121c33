// A look at an OpenEXR file's header before OpenEXR reads it. OpenEXR allocates an attribute's
// declared size, and the table of chunk offsets the data window implies, as soon as it opens a
// file: a forged size in a 300-byte file made it ask for 1.9 GB (found by fuzz_image_exr).
// Every attribute must fit in the file, the format's required attributes must be there, every
// channel's sampling must fit the data window, and the window must be small enough that the
// file could hold its offset table at all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace clrt::image_detail {

// Throws ImageError naming `path` when an attribute is larger than the bytes left, a required
// attribute is missing, a channel's sampling is below 1 or beyond the data window, or the data
// window needs more chunk offsets than `bytes` can hold or more pixels than clrt handles. A
// header cut short is left to OpenEXR, whose own error says so.
void check_exr_window(const std::vector<std::uint8_t>& bytes, const std::string& path);

}  // namespace clrt::image_detail
