// The FSF layout (see docs: "The FSF image format"): a 16-byte header of four uint32 (magic 575,
// width, height, frames), then 8-bit RGBA pixels, frame by frame, rows from the top.
#pragma once

#include <cstdint>

#include "image/image.hpp"
#include "image/input_file.hpp"

namespace clrt::image_detail {

constexpr std::uint32_t kFsfMagic = 575;
constexpr std::uint32_t kFsfHeaderBytes = 16;

// Reads and checks the header of an FSF file just opened: the magic (choosing the byte order),
// non-zero sizes that fit an Rgba8Image, and a file size equal to what the header describes.
FsfHeader read_checked_fsf_header(InputFile& file);

}  // namespace clrt::image_detail
