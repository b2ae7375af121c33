#include <string>
#include <vector>

#include "image/encoders.hpp"

namespace clrt::image_detail {

// Binary P6 with maxval 255; PPM has no alpha, so it is dropped.
void encode_ppm(const EightBitRows& rows, ByteSink& sink) {
  const std::string header =
      "P6\n" + std::to_string(rows.width()) + " " + std::to_string(rows.height()) + "\n255\n";
  sink.write(header.data(), header.size());
  std::vector<std::uint8_t> scratch(4 * static_cast<std::size_t>(rows.width()));
  for (int y = 0; y < rows.height(); ++y)
    sink.write(rows.rgb_row(0, y, scratch.data()), 3 * static_cast<std::size_t>(rows.width()));
}

}  // namespace clrt::image_detail
