#include <algorithm>
#include <cctype>

#include "image/decoders.hpp"
#include "image/placement.hpp"

namespace clrt {

AnyImage read_any_image(const std::string& path) {
  switch (format_from_path(path)) {
    case ImageFormat::Fsf:
      return read_fsf(path);
    case ImageFormat::Png:
      return read_png(path);
    case ImageFormat::Ppm:
      return read_ppm(path);
    case ImageFormat::Pfm:
      return read_pfm(path);
    case ImageFormat::Exr:
      break;
  }
  return read_exr(path);
}

Rgba8Image read_image(const std::string& path) {
  AnyImage image = read_any_image(path);
  if (auto* floats = std::get_if<FloatImage>(&image)) return quantize(*floats);
  return std::get<Rgba8Image>(std::move(image));
}

ImageInfo read_image_info(const std::string& path) {
  switch (format_from_path(path)) {
    case ImageFormat::Fsf:
      return image_detail::fsf_info(path);
    case ImageFormat::Png:
      return image_detail::png_info(path);
    case ImageFormat::Ppm:
      return image_detail::ppm_info(path);
    case ImageFormat::Pfm:
      return image_detail::pfm_info(path);
    case ImageFormat::Exr:
      break;
  }
  return image_detail::exr_info(path);
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
