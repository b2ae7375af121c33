// A look at an OpenEXR file's headers before OpenEXR reads them. OpenEXR allocates what a header
// declares as soon as it opens a file, and reads some values (channel lists, string vectors)
// until their own end rather than their declared size: forged files of a few hundred bytes made
// it ask for 1.8 and 1.9 GB (found by fuzz_image_exr). The walk reads every header as OpenEXR
// would and refuses a file where the two could disagree: names without their end, values that
// run past their size, missing required attributes, channel sampling outside the data window,
// and windows too large for the file's chunk table or for clrt.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/byte_span.hpp"

namespace clrt::image_detail {

// Throws ImageError naming `path` and the reason for any of the above; a file that does not
// start with OpenEXR's magic number is left to OpenEXR, whose own error names it.
void check_exr_window(ByteSpan bytes, const std::string& path);

}  // namespace clrt::image_detail
