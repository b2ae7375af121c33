#include "command_line.hpp"

#include <climits>
#include <iostream>

#include "cli/whole_number.hpp"
#include "cli/word_choice.hpp"
#include "image/image_info.hpp"
#include "image/output_target.hpp"

namespace clrt::img {

void add_format_option(CLI::App& command, std::optional<ImageFormat>& format) {
  command
      .add_option_function<std::string>(
          "--format", [&format](const std::string& name) { format = format_from_name(name); },
          "the output's format, needed for standard output (-); otherwise its extension")
      ->transform(word_choice(format_names()));
}

void add_exr_pixel_option(CLI::App& command, std::optional<ExrPixel>& pixel) {
  command
      .add_option_function<std::string>(
          "--exr-pixel",
          [&pixel](const std::string& name) {
            pixel = CLI::detail::to_lower(name) == "float" ? ExrPixel::Float : ExrPixel::Half;
          },
          "EXR channels: half or float (default: float when an input holds 32-bit floats)")
      ->transform(word_choice({"half", "float"}));
}

CLI::Option* add_frame_option(CLI::App& command, const std::string& name,
                              std::optional<int>& frame, const std::string& what) {
  const CLI::Validator whole = whole_number(1, INT_MAX);
  // Frames were once counted from 0 here: a 0 is most likely that habit, so say why it fails.
  const CLI::Validator from_one(
      [whole](std::string& text) {
        return parse_whole_number(text) == 0 ? "frames are counted from 1, so there is no frame 0"
                                             : whole(text);
      },
      "");
  return command.add_option(name, frame, what + " (counted from 1)")->transform(from_one);
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
    ImageOutput output = resolve_output(path, format);
    if (!output.is_stdout()) check_output_replaceable(output.path);
    return output;
  } catch (const ImageError& error) {
    throw UsageError(error.what());
  }
}

int frame_count(const AnyImage& image) {
  const auto* rgba = std::get_if<Rgba8Image>(&image);
  return rgba ? static_cast<int>(rgba->frames.size()) : 1;
}

AnyImage pick_frame(const AnyImage& image, std::optional<int> frame, const std::string& path,
                    const std::string& how) {
  const int count = frame_count(image);
  if (!frame && count > 1)
    throw ImageError(path + " holds " + std::to_string(count) + " frames: pick one with " + how);
  if (frame && (*frame < 1 || *frame > count))
    throw ImageError(path + " has no frame " + std::to_string(*frame) + ": it holds " +
                     (count == 1 ? "one frame" : "frames 1 to " + std::to_string(count)));
  if (frame && count > 1) return select_frame(std::get<Rgba8Image>(image), *frame);
  return image;
}

bool holds_float32(const std::string& path, ImageFormat format) {
  return format == ImageFormat::Pfm ||
         (format == ImageFormat::Exr && read_image_info(path).float32);
}

ExrPixel exr_pixel_for(std::optional<ExrPixel> option, bool float32) {
  return option.value_or(float32 ? ExrPixel::Float : ExrPixel::Half);
}

WriteOptions write_options_for(std::optional<ExrPixel> option, bool float32) {
  WriteOptions options{exr_pixel_for(option, float32)};
  options.warn = warn;
  return options;
}

void warn(const std::string& message) { std::cerr << "clrt-img: warning: " << message << "\n"; }

}  // namespace clrt::img
