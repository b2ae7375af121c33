// How clrt-view turns linear floats into the 8-bit pixels on the screen: the display transform
// clrt's writers use (image/display_transform.hpp), so that at exposure 0, gamma 1, no curve
// and no sRGB a float image shows the bytes clrt's PNG of it holds (a Whitted render's; with
// --srgb, a path-mode render's), and an 8-bit image (read as value / 255) shows its own bytes.
#pragma once

#include <cstdint>
#include <vector>

#include "image/display_transform.hpp"
#include "image/image.hpp"

namespace clrt::view {

// {exposure, gamma} as the viewer always took them, the curve and sRGB after.
using ToneSettings = DisplayTransform;

// Pixels as the window holds them: 0x00RRGGBB, row 0 at the top.
struct Canvas {
  int width = 0, height = 0;
  std::vector<std::uint32_t> pixels;
  std::uint32_t at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

std::uint32_t tone_map_pixel(const float* rgb, const ToneSettings& tone);

}  // namespace clrt::view
