// PNG through libpng's simplified API: it encodes into memory and reports errors by return value,
// so no longjmp crosses C++ frames; the bytes then go through the atomic writer.
#include <png.h>

#include <algorithm>
#include <cstring>

#include "image/encoders.hpp"

namespace clrt::image_detail {
namespace {

bool all_opaque(const std::vector<std::uint8_t>& rgba) {
  for (std::size_t i = 3; i < rgba.size(); i += 4)
    if (rgba[i] != 255) return false;
  return true;
}

std::vector<std::uint8_t> without_alpha(const std::vector<std::uint8_t>& rgba) {
  std::vector<std::uint8_t> rgb;
  rgb.reserve(rgba.size() / 4 * 3);
  for (std::size_t i = 0; i < rgba.size(); i += 4)
    rgb.insert(rgb.end(), rgba.begin() + i, rgba.begin() + i + 3);
  return rgb;
}

}  // namespace

// An opaque frame (everything clrt renders) is stored as RGB: a quarter smaller, same pixels.
std::vector<std::uint8_t> encode_png(const Rgba8Image& image) {
  const std::vector<std::uint8_t>& rgba = image.frames.front();
  const bool opaque = all_opaque(rgba);
  const std::vector<std::uint8_t> pixels = opaque ? without_alpha(rgba) : rgba;

  png_image header;
  std::memset(&header, 0, sizeof header);
  header.version = PNG_IMAGE_VERSION;
  header.width = static_cast<png_uint_32>(image.width);
  header.height = static_cast<png_uint_32>(image.height);
  header.format = opaque ? PNG_FORMAT_RGB : PNG_FORMAT_RGBA;

  // The bound is exact enough to succeed at once; if libpng still needs more it says how much.
  std::vector<std::uint8_t> png(PNG_IMAGE_PNG_SIZE_MAX(header));
  for (int attempt = 0; attempt < 2; ++attempt) {
    png_alloc_size_t size = png.size();
    if (png_image_write_to_memory(&header, png.data(), &size, 0, pixels.data(), 0, nullptr)) {
      png.resize(size);
      return png;
    }
    if (size <= png.size()) break;
    png.resize(size);
  }
  throw ImageError(std::string("PNG encoding failed: ") + header.message);
}

}  // namespace clrt::image_detail
