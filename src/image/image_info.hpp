// What a file holds, from its header alone: what `clrt-img info` prints.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "image/image.hpp"

namespace clrt {

struct ImageInfo {
  ImageFormat format = ImageFormat::Png;
  int width = 0, height = 0;
  std::uint64_t frames = 1;
  std::string channels;  // as stored, e.g. "RGB", "grey, alpha", "palette", "R, G, B"
  std::string samples;   // as stored, e.g. "8-bit", "16-bit float (half)", "32-bit float"
  bool float32 = false;  // samples that half floats cannot hold exactly (PFM, float EXR)
  std::optional<Placement> placement;
  std::vector<std::pair<std::string, std::string>> details;  // the format's own, in order
};

// By the path's extension; ImageError if it cannot be read.
ImageInfo read_image_info(const std::string& path);
// The same from the file's bytes in memory, in `format`.
ImageInfo decode_image_info(const ImageBytes& file, ImageFormat format);

// One "key: value" line each: format, width, height, frames, channels, samples, placement, then
// the details.
std::string info_text(const ImageInfo& info);

// Whether the format can record a placement (PNG, EXR).
bool records_placement(ImageFormat format);

}  // namespace clrt
