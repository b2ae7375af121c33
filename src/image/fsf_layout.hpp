// The FSF layout (see docs: "The FSF image format"): a 16-byte header of four uint32 (magic 575,
// width, height, frames), then 8-bit RGBA pixels, frame by frame, rows from the top.
#pragma once

#include <cstdint>

#include "image/byte_span.hpp"
#include "image/image.hpp"
#include "image/image_info.hpp"
#include "image/input_file.hpp"

namespace clrt::image_detail {

constexpr std::uint32_t kFsfMagic = 575;
constexpr std::uint32_t kFsfHeaderBytes = 16;

// The header at the start of `head` (a file of `file_bytes` bytes named `name`), checked: the
// magic (choosing the byte order; another format's signature is named), non-zero sizes that fit
// an Rgba8Image, and a file size equal to what the header describes.
FsfHeader checked_fsf_header(ByteSpan head, std::uint64_t file_bytes, const std::string& name);
// The same for a file just opened, reading only its header.
FsfHeader read_checked_fsf_header(InputFile& file);

ImageInfo fsf_header_info(const FsfHeader& header);

}  // namespace clrt::image_detail
