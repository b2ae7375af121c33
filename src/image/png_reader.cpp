// PNG through libpng's simplified API, which expands every bit depth and colour type (palette,
// grey, tRNS transparency, 16-bit) to the 8-bit RGBA we ask for and reports errors by return
// value instead of longjmp.
#include <png.h>

#include <climits>
#include <cstring>
#include <new>

#include "image/image.hpp"
#include "image/input_file.hpp"

namespace clrt {
namespace {

// Frees libpng's state on every exit between begin_read and finish_read (which frees it itself).
struct PngReadState {
  png_image image;
  PngReadState() {
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
  }
  ~PngReadState() { png_image_free(&image); }
  PngReadState(const PngReadState&) = delete;
  PngReadState& operator=(const PngReadState&) = delete;
};

}  // namespace

Rgba8Image read_png(const std::string& path) {
  const std::vector<std::uint8_t> bytes = image_detail::read_file_bytes(path);
  PngReadState state;
  png_image& image = state.image;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
    throw ImageError(path + ": not a readable PNG: " + image.message);
  // Without this libpng would take 16-bit samples as linear light and re-encode them to sRGB,
  // brightening them; clrt treats 8- and 16-bit values alike, as plain display values.
  image.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
  image.format = PNG_FORMAT_RGBA;
  if (image.width > INT_MAX / 4 || image.height > INT_MAX)
    throw ImageError(path + ": the PNG is too large (" + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + ")");

  Rgba8Image out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  try {
    out.frames.emplace_back(4 * std::size_t{image.width} * image.height);
  } catch (const std::bad_alloc&) {
    throw ImageError(path + ": not enough memory for a " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " PNG");
  }
  if (!png_image_finish_read(&image, nullptr, out.frames.front().data(), 0, nullptr))
    throw ImageError(path + ": not a readable PNG: " + image.message);
  return out;
}

}  // namespace clrt
