#include <cstddef>
#include <cstdint>

#include "image/eight_bit_rows.hpp"
#include "image/image.hpp"
#include "image/image_checks.hpp"

namespace clrt {

Rgba8Image quantize(const FloatImage& image, const DisplayTransform& display) {
  image_detail::check_image(image, "cannot quantize");
  const image_detail::EightBitRows rows(image, display);
  const std::size_t row_bytes = 4 * static_cast<std::size_t>(image.width);
  std::vector<std::uint8_t> rgba(row_bytes * static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y)
    rows.rgba_row(0, y, rgba.data() + static_cast<std::size_t>(y) * row_bytes);
  return Rgba8Image(image.width, image.height, {std::move(rgba)}, image.placement);
}

FloatImage to_float(const Rgba8Image& image, std::size_t frame) {
  image_detail::check_image(image, "cannot convert to float");
  const std::vector<std::uint8_t>& rgba = image.frames.at(frame);
  std::vector<float> rgb(rgba.size() / 4 * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i)
    rgb[i] = static_cast<float>(rgba[i + i / 3]) / 255.0f;
  return FloatImage(image.width, image.height, std::move(rgb), image.placement);
}

}  // namespace clrt
