#include <cmath>
#include <cstddef>
#include <cstdint>

#include "image/image.hpp"
#include "image/image_checks.hpp"

namespace clrt {
namespace {

// Written so that NaN fails the first test and becomes 0 (a black pixel rather than undefined
// behaviour in the conversion); +inf saturates to 255 like any value above 1.
std::uint8_t quantize_channel(float value) {
  if (!(value > 0.0f)) return 0;
  if (value >= 1.0f) return 255;
  return static_cast<std::uint8_t>(std::lround(static_cast<double>(value) * 255.0));
}

}  // namespace

Rgba8Image quantize(const FloatImage& image) {
  image_detail::check_image(image, "cannot quantize");
  Rgba8Image out;
  out.width = image.width;
  out.height = image.height;
  const std::size_t pixels = image.rgb.size() / 3;
  std::vector<std::uint8_t> rgba(4 * pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    for (std::size_t c = 0; c < 3; ++c) rgba[4 * i + c] = quantize_channel(image.rgb[3 * i + c]);
    rgba[4 * i + 3] = 255;
  }
  out.frames.push_back(std::move(rgba));
  return out;
}

}  // namespace clrt
