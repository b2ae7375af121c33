// A rectangle of an image's pixels: how work travels from the command line to the kernels, so
// a region costs what its pixels cost.
#pragma once

#include <cstdint>
#include <string>

namespace clrt {

// Columns [x, x + width), rows [y, y + height).
struct PixelRect {
  std::uint32_t x = 0, y = 0, width = 0, height = 0;
  std::uint64_t pixel_count() const { return std::uint64_t{width} * height; }
};

// "x0,x1,y0,y1", half-open, as --pixel-bounds takes it.
inline std::string describe(const PixelRect& r) {
  return std::to_string(r.x) + "," + std::to_string(std::uint64_t{r.x} + r.width) + "," +
         std::to_string(r.y) + "," + std::to_string(std::uint64_t{r.y} + r.height);
}

}  // namespace clrt
