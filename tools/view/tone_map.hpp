// How clrt-view turns linear floats into the 8-bit pixels on the screen: exposure (in stops)
// scales the value, gamma encodes it, then clrt's own quantisation (clamp to [0, 1], scale by
// 255, round to nearest). At exposure 0 and gamma 1 a float image shows the bytes clrt's PNG of
// it holds, and an 8-bit image (read as value / 255) shows its own bytes.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.hpp"

namespace clrt::view {

struct ToneSettings {
  double exposure = 0;  // stops: each +1 doubles every value
  double gamma = 1;     // the value shown is value^(1/gamma)
};

// Pixels as the window holds them: 0x00RRGGBB, row 0 at the top.
struct Canvas {
  int width = 0, height = 0;
  std::vector<std::uint32_t> pixels;
  std::uint32_t at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

std::uint8_t tone_map_channel(float value, const ToneSettings& tone);
std::uint32_t tone_map_pixel(const float* rgb, const ToneSettings& tone);

}  // namespace clrt::view
