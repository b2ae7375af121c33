#include <string>

#include "image/byte_order.hpp"
#include "image/encoders.hpp"

namespace clrt::image_detail {

// Colour PFM: "PF", the size, then the scale -1 whose sign marks little-endian floats; rows go
// from the bottom up, as PFM requires. Values are written as rendered, unclamped.
std::vector<std::uint8_t> encode_pfm(const FloatImage& image) {
  const std::string header =
      "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  std::vector<std::uint8_t> pfm(header.begin(), header.end());
  pfm.reserve(header.size() + 4 * image.rgb.size());
  const std::size_t row_floats = 3 * static_cast<std::size_t>(image.width);
  for (std::size_t row = static_cast<std::size_t>(image.height); row-- > 0;)
    for (std::size_t i = 0; i < row_floats; ++i)
      append_f32_le(pfm, image.rgb[row * row_floats + i]);
  return pfm;
}

}  // namespace clrt::image_detail
