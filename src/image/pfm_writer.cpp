#include <string>
#include <vector>

#include "image/byte_order.hpp"
#include "image/encoders.hpp"

namespace clrt::image_detail {

// Colour PFM: "PF", the size, then the scale -1 whose sign marks little-endian floats; rows go
// from the bottom up, as PFM requires. Values are written as rendered, unclamped.
void encode_pfm(const FloatImage& image, ByteSink& sink) {
  const std::string header =
      "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  sink.write(header.data(), header.size());
  const std::size_t row_floats = 3 * static_cast<std::size_t>(image.width);
  std::vector<std::uint8_t> row(4 * row_floats);
  for (std::size_t y = static_cast<std::size_t>(image.height); y-- > 0;) {
    const float* in = image.rgb.data() + y * row_floats;
    for (std::size_t i = 0; i < row_floats; ++i) store_u32_le(row.data() + 4 * i, float_bits(in[i]));
    sink.write(row.data(), row.size());
  }
}

}  // namespace clrt::image_detail
