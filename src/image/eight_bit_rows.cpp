#include "image/eight_bit_rows.hpp"

#include <cmath>

namespace clrt::image_detail {
namespace {

std::size_t row_offset(int y, int width, std::size_t channels) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) * channels;
}

}  // namespace

// NaN fails the first test and becomes 0 (a black pixel rather than undefined behaviour in the
// conversion); +inf saturates to 255 like any value above 1. value * 255 is exact in double, so
// lround is the only rounding.
std::uint8_t quantize_channel(float value) noexcept {
  if (!(value > 0.0f)) return 0;
  if (value >= 1.0f) return 255;
  return static_cast<std::uint8_t>(std::lround(static_cast<double>(value) * 255.0));
}

bool EightBitRows::opaque() const {
  if (float_) return true;
  const std::vector<std::uint8_t>& rgba = rgba_->frames.front();
  for (std::size_t i = 3; i < rgba.size(); i += 4)
    if (rgba[i] != 255) return false;
  return true;
}

const std::uint8_t* EightBitRows::rgba_row(std::size_t frame, int y,
                                           std::uint8_t* scratch) const noexcept {
  if (rgba_) return rgba_->frames[frame].data() + row_offset(y, rgba_->width, 4);
  const float* in = float_->rgb.data() + row_offset(y, float_->width, 3);
  for (std::size_t x = 0; x < static_cast<std::size_t>(float_->width); ++x) {
    for (std::size_t c = 0; c < 3; ++c) scratch[4 * x + c] = quantize_channel(in[3 * x + c]);
    scratch[4 * x + 3] = 255;
  }
  return scratch;
}

const std::uint8_t* EightBitRows::rgb_row(std::size_t frame, int y,
                                          std::uint8_t* scratch) const noexcept {
  const std::size_t samples = 3 * static_cast<std::size_t>(width());
  if (float_) {
    const float* in = float_->rgb.data() + row_offset(y, float_->width, 3);
    for (std::size_t i = 0; i < samples; ++i) scratch[i] = quantize_channel(in[i]);
    return scratch;
  }
  const std::uint8_t* in = rgba_->frames[frame].data() + row_offset(y, rgba_->width, 4);
  for (std::size_t i = 0; i < samples; ++i) scratch[i] = in[i + i / 3];
  return scratch;
}

}  // namespace clrt::image_detail
