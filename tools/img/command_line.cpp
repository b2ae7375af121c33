#include "command_line.hpp"

#include <climits>
#include <iostream>

#include "image/image_info.hpp"

namespace clrt::img {

void add_format_option(CLI::App& command, std::optional<ImageFormat>& format) {
  command
      .add_option_function<std::string>(
          "--format", [&format](const std::string& name) { format = format_from_name(name); },
          "the output's format, needed for standard output (-); otherwise its extension")
      ->check(CLI::IsMember(format_names(), CLI::ignore_case));
}

void add_exr_pixel_option(CLI::App& command, std::optional<ExrPixel>& pixel) {
  command
      .add_option_function<std::string>(
          "--exr-pixel",
          [&pixel](const std::string& name) {
            pixel = CLI::detail::to_lower(name) == "float" ? ExrPixel::Float : ExrPixel::Half;
          },
          "EXR channels: half or float (default: float when an input holds 32-bit floats)")
      ->check(CLI::IsMember({"half", "float"}, CLI::ignore_case));
}

void add_frame_option(CLI::App& command, std::optional<int>& frame, const std::string& what) {
  command.add_option("--frame", frame, what)->check(CLI::Range(0, INT_MAX));
}

ImageFormat input_format(const std::string& path) {
  try {
    return format_from_path(path);
  } catch (const ImageError& error) {
    throw UsageError(error.what());
  }
}

ImageOutput output_argument(const std::string& path, std::optional<ImageFormat> format) {
  try {
    return resolve_output(path, format);
  } catch (const ImageError& error) {
    throw UsageError(error.what());
  }
}

AnyImage pick_frame(AnyImage image, std::optional<int> frame, const std::string& path) {
  if (auto* rgba = std::get_if<Rgba8Image>(&image)) {
    if (frame) return select_frame(*rgba, *frame);
    if (rgba->frames.size() > 1)
      throw ImageError(path + " holds " + std::to_string(rgba->frames.size()) +
                       " frames: pick one with --frame N (counted from 0)");
    return image;
  }
  if (frame && *frame != 0)
    throw ImageError(path + " has no frame " + std::to_string(*frame) + ": it holds one");
  return image;
}

bool holds_float32(const std::string& path, ImageFormat format) {
  return format == ImageFormat::Pfm ||
         (format == ImageFormat::Exr && read_image_info(path).float32);
}

ExrPixel exr_pixel_for(std::optional<ExrPixel> option, bool float32) {
  return option.value_or(float32 ? ExrPixel::Float : ExrPixel::Half);
}

void warn(const std::string& message) { std::cerr << "clrt-img: warning: " << message << "\n"; }

}  // namespace clrt::img
