#include <algorithm>
#include <cctype>

#include "image/content_kind.hpp"
#include "image/decoders.hpp"
#include "image/fsf_layout.hpp"
#include "image/input_file.hpp"
#include "image/placement.hpp"

namespace clrt {

AnyImage decode_image(const ImageBytes& file, ImageFormat format, Frames frames) {
  image_detail::check_content(file.bytes.head(image_detail::kContentHeadBytes), format, file.name);
  switch (format) {
    case ImageFormat::Fsf:
      return image_detail::fsf_pixels(file, frames);
    case ImageFormat::Png:
      return image_detail::png_pixels(file);
    case ImageFormat::Ppm:
      return image_detail::ppm_pixels(file);
    case ImageFormat::Pfm:
      return image_detail::pfm_pixels(file);
    case ImageFormat::Exr:
      break;
  }
  return image_detail::exr_pixels(file);
}

ImageInfo decode_image_info(const ImageBytes& file, ImageFormat format) {
  image_detail::check_content(file.bytes.head(image_detail::kContentHeadBytes), format, file.name);
  switch (format) {
    case ImageFormat::Fsf:
      return image_detail::fsf_info(file);
    case ImageFormat::Png:
      return image_detail::png_info(file);
    case ImageFormat::Ppm:
      return image_detail::ppm_info(file);
    case ImageFormat::Pfm:
      return image_detail::pfm_info(file);
    case ImageFormat::Exr:
      break;
  }
  return image_detail::exr_info(file);
}

namespace {

// The file at `path` read whole, then decoded in place as `format`.
AnyImage decode_file(const std::string& path, ImageFormat format) {
  const std::vector<std::uint8_t> bytes = image_detail::read_file_bytes(path);
  return decode_image({bytes, path}, format);
}

}  // namespace

AnyImage read_any_image(const std::string& path) {
  const ImageFormat format = format_from_path(path);
  if (format == ImageFormat::Fsf) return read_fsf(path);
  return decode_file(path, format);
}

Rgba8Image read_png(const std::string& path) {
  return std::get<Rgba8Image>(decode_file(path, ImageFormat::Png));
}

Rgba8Image read_ppm(const std::string& path) {
  return std::get<Rgba8Image>(decode_file(path, ImageFormat::Ppm));
}

FloatImage read_pfm(const std::string& path) {
  return std::get<FloatImage>(decode_file(path, ImageFormat::Pfm));
}

FloatImage read_exr(const std::string& path) {
  return std::get<FloatImage>(decode_file(path, ImageFormat::Exr));
}

Rgba8Image read_image(const std::string& path) {
  AnyImage image = read_any_image(path);
  if (auto* floats = std::get_if<FloatImage>(&image)) return quantize(*floats);
  return std::get<Rgba8Image>(std::move(image));
}

// An FSF animation's header alone is read; the other formats are read whole, as their decoders
// need the file in memory anyway.
ImageInfo read_image_info(const std::string& path) {
  const ImageFormat format = format_from_path(path);
  if (format == ImageFormat::Fsf) return image_detail::fsf_header_info(read_fsf_header(path));
  const std::vector<std::uint8_t> bytes = image_detail::read_file_bytes(path);
  return decode_image_info({bytes, path}, format);
}

ImageInfo image_detail::basic_info(ImageFormat format, int width, int height,
                                  std::string channels, std::string samples) {
  ImageInfo info;
  info.format = format;
  info.width = width;
  info.height = height;
  info.channels = std::move(channels);
  info.samples = std::move(samples);
  return info;
}

bool records_placement(ImageFormat format) {
  return format == ImageFormat::Png || format == ImageFormat::Exr;
}

std::string info_text(const ImageInfo& info) {
  std::string name = format_name(info.format);
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  const std::string placement =
      info.placement
          ? image_detail::placement_text(*info.placement, info.width, info.height)
          : records_placement(info.format) ? "none (the whole frame)"
                                           : "none (" + name + " cannot record one)";
  std::string text = "format: " + name + "\nwidth: " + std::to_string(info.width) +
                     "\nheight: " + std::to_string(info.height) +
                     "\nframes: " + std::to_string(info.frames) + "\nchannels: " + info.channels +
                     "\nsamples: " + info.samples + "\nplacement: " + placement + "\n";
  for (const auto& [key, value] : info.details) text += key + ": " + value + "\n";
  return text;
}

Rgba8Image select_frame(const Rgba8Image& image, int frame) {
  if (frame < 1 || static_cast<std::size_t>(frame) > image.frames.size())
    throw ImageError("there is no frame " + std::to_string(frame) + ": the image has " +
                     std::to_string(image.frames.size()) + " frame(s), counted from 1");
  return Rgba8Image(image.width, image.height,
                    {image.frames[static_cast<std::size_t>(frame) - 1]}, image.placement);
}

}  // namespace clrt
