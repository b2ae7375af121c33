#include <string>

#include "image/encoders.hpp"

namespace clrt::image_detail {

// Binary P6 with maxval 255; PPM has no alpha, so it is dropped.
std::vector<std::uint8_t> encode_ppm(const Rgba8Image& image) {
  const std::string header =
      "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  const std::vector<std::uint8_t>& rgba = image.frames.front();
  std::vector<std::uint8_t> ppm(header.begin(), header.end());
  ppm.reserve(header.size() + rgba.size() / 4 * 3);
  for (std::size_t i = 0; i < rgba.size(); i += 4)
    ppm.insert(ppm.end(), rgba.begin() + i, rgba.begin() + i + 3);
  return ppm;
}

}  // namespace clrt::image_detail
