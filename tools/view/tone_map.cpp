#include "tone_map.hpp"

namespace clrt::view {

std::uint32_t tone_map_pixel(const float* rgb, const ToneSettings& tone) {
  return std::uint32_t{display_byte(rgb[0], tone)} << 16 |
         std::uint32_t{display_byte(rgb[1], tone)} << 8 | display_byte(rgb[2], tone);
}

}  // namespace clrt::view
