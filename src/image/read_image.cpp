#include "image/image.hpp"

namespace clrt {

Rgba8Image read_image(const std::string& path) {
  switch (format_from_path(path)) {
    case ImageFormat::Fsf:
      return read_fsf(path);
    case ImageFormat::Png:
      return read_png(path);
    case ImageFormat::Ppm:
      return read_ppm(path);
    case ImageFormat::Pfm:
      break;
  }
  throw ImageError(path + ": reading PFM is not supported; readable image types: .fsf, .png, .ppm");
}

Rgba8Image select_frame(const Rgba8Image& image, int frame) {
  if (frame < 0 || static_cast<std::size_t>(frame) >= image.frames.size())
    throw ImageError("there is no frame " + std::to_string(frame) + ": the image has " +
                     std::to_string(image.frames.size()) + " frame(s), counted from 0");
  Rgba8Image out;
  out.width = image.width;
  out.height = image.height;
  out.frames.push_back(image.frames[static_cast<std::size_t>(frame)]);
  return out;
}

}  // namespace clrt
