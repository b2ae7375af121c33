#include <cstring>

#include "image/decoders.hpp"
#include "image/fsf_layout.hpp"

namespace clrt {
namespace {

// An image of `frames` empty frames of the header's size, each filled by `fill(frame, index)`.
template <typename Fill>
Rgba8Image fsf_image(const FsfHeader& header, std::size_t frames, const Fill& fill) {
  Rgba8Image image;
  image.width = static_cast<int>(header.width);
  image.height = static_cast<int>(header.height);
  const std::size_t frame_bytes = 4 * std::size_t{header.width} * header.height;
  image.frames.resize(frames);
  for (std::size_t i = 0; i < frames; ++i) {
    image.frames[i].resize(frame_bytes);
    fill(image.frames[i], i);
  }
  return image;
}

}  // namespace

// From a path the frames are read straight into place: an animation is not held twice.
Rgba8Image read_fsf(const std::string& path) {
  image_detail::InputFile file(path);
  const FsfHeader header = image_detail::read_checked_fsf_header(file);
  return fsf_image(header, header.frames, [&](std::vector<std::uint8_t>& frame, std::size_t) {
    file.read_exact(frame.data(), frame.size());
  });
}

Rgba8Image image_detail::fsf_pixels(const ImageBytes& file, Frames frames) {
  const FsfHeader header =
      checked_fsf_header(file.bytes.head(kFsfHeaderBytes), file.bytes.size(), file.name);
  const std::size_t count = frames == Frames::First ? 1 : header.frames;
  return fsf_image(header, count, [&](std::vector<std::uint8_t>& frame, std::size_t i) {
    std::memcpy(frame.data(), file.bytes.data() + kFsfHeaderBytes + i * frame.size(), frame.size());
  });
}

ImageInfo image_detail::fsf_info(const ImageBytes& file) {
  return fsf_header_info(
      checked_fsf_header(file.bytes.head(kFsfHeaderBytes), file.bytes.size(), file.name));
}

}  // namespace clrt
