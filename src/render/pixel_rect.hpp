// A rectangle of an image's pixels: how work travels from the command line to the kernels, so
// a region costs what its pixels cost.
#pragma once

#include <cstdint>

namespace clrt {

// Columns [x, x + width), rows [y, y + height).
struct PixelRect {
  std::uint32_t x = 0, y = 0, width = 0, height = 0;
  std::uint64_t pixel_count() const { return std::uint64_t{width} * height; }
};

}  // namespace clrt
