#include "tone_map.hpp"

#include <algorithm>
#include <cmath>

#include "image/eight_bit_rows.hpp"

namespace clrt::view {

std::uint8_t tone_map_channel(float value, const ToneSettings& tone) {
  if (tone.exposure == 0 && tone.gamma == 1) return image_detail::quantize_channel(value);
  const double scaled = static_cast<double>(value) * std::exp2(tone.exposure);
  // Zero, negatives and NaN quantise to 0 without the power, which is undefined for them.
  if (!(scaled > 0)) return image_detail::quantize_channel(0.0f);
  return image_detail::quantize_channel(
      static_cast<float>(std::pow(std::min(scaled, 1.0), 1 / tone.gamma)));
}

std::uint32_t tone_map_pixel(const float* rgb, const ToneSettings& tone) {
  return std::uint32_t{tone_map_channel(rgb[0], tone)} << 16 |
         std::uint32_t{tone_map_channel(rgb[1], tone)} << 8 | tone_map_channel(rgb[2], tone);
}

}  // namespace clrt::view
