#include "render/pixel_store.hpp"

#include "image/eight_bit_rows.hpp"

namespace clrt {

void FloatPixelStore::store(std::uint64_t first, std::uint32_t count, const dev::f4* pixels) {
  float* rgb = image_.rgb.data() + 3 * first;
  for (std::uint32_t p = 0; p < count; ++p) {
    rgb[3 * p + 0] = pixels[p].x;
    rgb[3 * p + 1] = pixels[p].y;
    rgb[3 * p + 2] = pixels[p].z;
  }
}

void BytePixelStore::store(std::uint64_t first, std::uint32_t count, const dev::f4* pixels) {
  using image_detail::quantize_channel;
  std::uint8_t* rgba = image_.frames.front().data() + 4 * first;
  for (std::uint32_t p = 0; p < count; ++p) {
    rgba[4 * p + 0] = quantize_channel(pixels[p].x);
    rgba[4 * p + 1] = quantize_channel(pixels[p].y);
    rgba[4 * p + 2] = quantize_channel(pixels[p].z);
    rgba[4 * p + 3] = 255;
  }
}

}  // namespace clrt
