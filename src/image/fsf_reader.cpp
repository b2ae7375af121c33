#include "image/fsf_layout.hpp"

namespace clrt {

Rgba8Image read_fsf(const std::string& path) {
  image_detail::InputFile file(path);
  const FsfHeader header = image_detail::read_checked_fsf_header(file);
  Rgba8Image image;
  image.width = static_cast<int>(header.width);
  image.height = static_cast<int>(header.height);
  const std::size_t frame_bytes = 4 * std::size_t{header.width} * header.height;
  image.frames.resize(header.frames);
  for (std::vector<std::uint8_t>& frame : image.frames) {
    frame.resize(frame_bytes);
    file.read_exact(frame.data(), frame.size());
  }
  return image;
}

}  // namespace clrt
