#include "image/eight_bit_rows.hpp"

namespace clrt::image_detail {
namespace {

std::size_t row_offset(int y, int width, std::size_t channels) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) * channels;
}

// A template over the channel's conversion, so that the contract's quantisation alone keeps
// loops the compiler can vectorise.
// The contract's quantisation as a lambda: a function pointer might stay an indirect call.
const auto kQuantize = [](float value) { return quantize_channel(value); };

template <typename Channel>
void float_rgba_row(const float* in, std::size_t width, std::uint8_t* out, Channel channel) {
  for (std::size_t x = 0; x < width; ++x) {
    for (std::size_t c = 0; c < 3; ++c) out[4 * x + c] = channel(in[3 * x + c]);
    out[4 * x + 3] = 255;
  }
}

template <typename Channel>
void float_rgb_row(const float* in, std::size_t samples, std::uint8_t* out, Channel channel) {
  for (std::size_t i = 0; i < samples; ++i) out[i] = channel(in[i]);
}

}  // namespace

// NaN fails the first comparison and becomes 0 (a black pixel rather than undefined behaviour
// in the conversion); +inf saturates to 255 like any value above 1. value * 255 is exact in
// double and so is adding 0.5, so the truncation is the only rounding: to nearest, ties up, which
// for these non-negative values is what lround does (the same byte for each of the 2^32 floats).
// No call, and selects the compiler can turn into min/max (this file is compiled with
// -fno-trapping-math, which allows it), so that the row loops below vectorise: lround cost
// 7 ns a channel, most of a PPM's write time.
std::uint8_t quantize_channel(float value) noexcept {
  float clamped = value > 0.0f ? value : 0.0f;
  clamped = clamped < 1.0f ? clamped : 1.0f;
  return static_cast<std::uint8_t>(static_cast<int>(static_cast<double>(clamped) * 255.0 + 0.5));
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
  const std::size_t width = static_cast<std::size_t>(float_->width);
  if (display_.identity())
    float_rgba_row(in, width, scratch, kQuantize);
  else
    float_rgba_row(in, width, scratch, [this](float v) { return display_byte(v, display_); });
  return scratch;
}

const std::uint8_t* EightBitRows::rgb_row(std::size_t frame, int y,
                                          std::uint8_t* scratch) const noexcept {
  const std::size_t samples = 3 * static_cast<std::size_t>(width());
  if (float_) {
    const float* in = float_->rgb.data() + row_offset(y, float_->width, 3);
    if (display_.identity())
      float_rgb_row(in, samples, scratch, kQuantize);
    else
      float_rgb_row(in, samples, scratch, [this](float v) { return display_byte(v, display_); });
    return scratch;
  }
  const std::uint8_t* in = rgba_->frames[frame].data() + row_offset(y, rgba_->width, 4);
  for (std::size_t i = 0; i < samples; ++i) scratch[i] = in[i + i / 3];
  return scratch;
}

}  // namespace clrt::image_detail
