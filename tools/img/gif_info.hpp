// `clrt-img info` of a GIF (the animations `convert` writes): its size, frames and frame delays,
// read record by record without decoding a pixel, so that any GIF is described in constant
// memory.
#pragma once

#include <string>

namespace clrt::img {

// Its "key: value" lines, as info_text() writes them for the other formats; ImageError when the
// file cannot be read as a GIF.
std::string gif_info_text(const std::string& path);

}  // namespace clrt::img
