#include "image/atomic_file.hpp"
#include "image/encoders.hpp"
#include "image/image_checks.hpp"

namespace clrt {
namespace {

using image_detail::encode_pfm;
using image_detail::encode_png;
using image_detail::encode_ppm;

// Bytes to value / 255, so an 8-bit image saved as PFM keeps its values exactly; alpha is dropped.
FloatImage to_float(const Rgba8Image& image) {
  FloatImage out;
  out.width = image.width;
  out.height = image.height;
  const std::vector<std::uint8_t>& rgba = image.frames.front();
  out.rgb.reserve(rgba.size() / 4 * 3);
  for (std::size_t i = 0; i < rgba.size(); ++i)
    if (i % 4 != 3) out.rgb.push_back(static_cast<float>(rgba[i]) / 255.0f);
  return out;
}

template <typename Encode, typename Image>
void encode_and_write(const std::string& path, Encode encode, const Image& image) {
  std::vector<std::uint8_t> bytes;
  try {
    bytes = encode(image);
  } catch (const ImageError& error) {
    throw ImageError("cannot write " + path + ": " + error.what());
  }
  image_detail::write_file_atomically(path, bytes);
}

}  // namespace

void write_image(const std::string& path, const FloatImage& image) {
  const ImageFormat format = format_from_path(path);
  image_detail::check_image(image, "cannot write " + path);
  if (format == ImageFormat::Pfm)
    encode_and_write(path, encode_pfm, image);
  else
    write_image(path, quantize(image));
}

void write_image(const std::string& path, const Rgba8Image& image) {
  const ImageFormat format = format_from_path(path);
  image_detail::check_image(image, "cannot write " + path);
  switch (format) {
    case ImageFormat::Fsf:
      return image_detail::write_fsf(path, image);
    case ImageFormat::Png:
      return encode_and_write(path, encode_png, image);
    case ImageFormat::Ppm:
      return encode_and_write(path, encode_ppm, image);
    case ImageFormat::Pfm:
      return encode_and_write(path, encode_pfm, to_float(image));
  }
}

}  // namespace clrt
