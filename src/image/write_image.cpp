#include <unistd.h>

#include "image/byte_sink.hpp"
#include "image/encoders.hpp"
#include "image/image_checks.hpp"
#include "image/output_target.hpp"
#include "image/sink_error.hpp"

namespace clrt {
namespace {

using image_detail::ByteSink;
using image_detail::EightBitRows;

// The float encoders take an 8-bit image as value / 255.
const FloatImage& as_float(const FloatImage& image) { return image; }
FloatImage as_float(const Rgba8Image& image) { return to_float(image); }

// A float image's rows through the display transform; an 8-bit image's bytes as they are.
EightBitRows rows_of(const FloatImage& image, const WriteOptions& options) {
  return EightBitRows(image, options.display);
}
EightBitRows rows_of(const Rgba8Image& image, const WriteOptions&) { return EightBitRows(image); }

template <typename Image>
void encode(ImageFormat format, const Image& image, const WriteOptions& options, ByteSink& sink) {
  switch (format) {
    case ImageFormat::Fsf:
      return image_detail::encode_fsf(rows_of(image, options), sink);
    case ImageFormat::Png:
      return image_detail::encode_png(rows_of(image, options), options.png, sink, options.samples);
    case ImageFormat::Ppm:
      return image_detail::encode_ppm(rows_of(image, options), sink);
    case ImageFormat::Pfm:
      return image_detail::encode_pfm(as_float(image), sink);
    case ImageFormat::Exr:
      return image_detail::encode_exr(as_float(image), options.exr_pixel, options.warn, sink,
                                       options.samples);
  }
}

// An encoder's error and warnings get the output's name; a failing output's error already has
// it.
template <typename Image>
void encode_into(ByteSink& sink, const std::string& name, ImageFormat format, const Image& image,
                 const WriteOptions& options) {
  WriteOptions named = options;
  if (options.warn)
    named.warn = [&](const std::string& message) { options.warn(name + ": " + message); };
  try {
    encode(format, image, named, sink);
  } catch (const image_detail::SinkError&) {
    throw;
  } catch (const ImageError& error) {
    throw ImageError("cannot write " + name + ": " + error.what());
  }
  sink.finish();
}

// What can be refused before the output is touched.
template <typename Image>
void check_writable(const Image& image, ImageFormat format, const WriteOptions& options,
                    const std::string& name) {
  image_detail::check_image(image, "cannot write " + name);
  try {
    if (format == ImageFormat::Png) image_detail::check_png_encoding(options.png);
  } catch (const ImageError& error) {
    throw ImageError("cannot write " + name + ": " + error.what());
  }
}

template <typename Image>
void write_file(const std::string& path, ImageFormat format, const Image& image,
                const WriteOptions& options) {
  check_writable(image, format, options, path);
  encode_into(*image_detail::open_output_sink({path, format}), path, format, image, options);
}

template <typename Image>
void write_fd(int fd, ImageFormat format, const Image& image, const WriteOptions& options) {
  const std::string name =
      fd == STDOUT_FILENO ? "standard output" : "file descriptor " + std::to_string(fd);
  check_writable(image, format, options, name);
  image_detail::FdSink sink(fd, name);
  encode_into(sink, name, format, image, options);
}

template <typename Image>
void write_output(const ImageOutput& output, const Image& image, const WriteOptions& options) {
  if (output.is_stdout())
    write_fd(STDOUT_FILENO, output.format, image, options);
  else
    write_file(output.path, output.format, image, options);
}

// The extension's format; a device or FIFO without one (/dev/null) gets clrt's default.
ImageFormat default_format(const std::string& path) {
  if (!format_of_extension(path) && find_output_target(path).stream) return ImageFormat::Png;
  return format_from_path(path);
}

}  // namespace

void write_image(const std::string& path, const FloatImage& image, const WriteOptions& options) {
  write_file(path, default_format(path), image, options);
}

void write_image(const std::string& path, const Rgba8Image& image, const WriteOptions& options) {
  write_file(path, default_format(path), image, options);
}

void write_image(const ImageOutput& output, const FloatImage& image, const WriteOptions& options) {
  write_output(output, image, options);
}

void write_image(const ImageOutput& output, const Rgba8Image& image, const WriteOptions& options) {
  write_output(output, image, options);
}

void write_image_to_fd(int fd, ImageFormat format, const FloatImage& image,
                       const WriteOptions& options) {
  write_fd(fd, format, image, options);
}

void write_image_to_fd(int fd, ImageFormat format, const Rgba8Image& image,
                       const WriteOptions& options) {
  write_fd(fd, format, image, options);
}

ImageOutput resolve_output(const std::string& path, std::optional<ImageFormat> format) {
  if (path == kStdoutPath) {
    if (!format) throw ImageError("writing to standard output needs the image format given");
    if (::isatty(STDOUT_FILENO))
      throw ImageError("standard output is a terminal; redirect it to a file or a pipe");
    return {path, *format};
  }
  refuse_folder(path);
  if (!format) return {path, default_format(path)};
  const std::optional<ImageFormat> named = format_of_extension(path);
  if (named && *named != *format)
    throw ImageError(path + ": the extension names " + format_name(*named) +
                     " but the format asked for is " + format_name(*format));
  return {path, *format};
}

}  // namespace clrt
