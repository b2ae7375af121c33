// clrt-img convert IN OUT: any format clrt reads into any it writes. 8-bit to 8-bit and float
// to float keep every value; float to 8-bit quantises as clrt does, after --exposure,
// --tonemap and --srgb when asked; 8-bit to float gives value / 255. All frames of an FSF go
// into an FSF, or into one file each through a pattern such as turn-%04d.png, or into an
// animated GIF at --fps frames per second; other outputs take the frame --frame names.
#include <cmath>
#include <memory>
#include <optional>

#include "cli/decimal_number.hpp"
#include "cli/word_choice.hpp"
#include "command_line.hpp"
#include "frame_pattern.hpp"
#include "gif_writer.hpp"
#include "image/image_info.hpp"
#include "memory_need.hpp"

namespace clrt::img {
namespace {

struct ConvertOptions {
  std::string input, output;
  std::optional<int> frame;
  std::optional<ImageFormat> format;
  std::optional<ExrPixel> exr_pixel;
  double fps = 25;
  DisplayTransform display;  // float to 8-bit only
};

// The display transform shapes a float image's way into 8 bits; anywhere else it would be
// dropped in silence.
void check_display(const ConvertOptions& options, ImageFormat input, bool float_output) {
  if (options.display.identity()) return;
  const char* asked = "--exposure, --tonemap and --srgb apply where a float image (pfm, exr) "
                      "becomes 8-bit; ";
  if (!holds_floats(input))
    throw UsageError(asked + options.input + " holds 8-bit values already");
  if (float_output)
    throw UsageError(asked + options.output + " keeps the floats as they are");
}

void write_converted(const std::string& path, const ImageOutput& output, const AnyImage& image,
                     const WriteOptions& options) {
  const std::optional<Placement> placement =
      std::visit([](const auto& i) { return i.placement; }, image);
  if (placement && !records_placement(output.format))
    warn(path + ": " + format_name(output.format) +
         " cannot record the placement; only the tile's pixels are written");
  std::visit([&](const auto& i) { write_image(output, i, options); }, image);
}

const char kHowToPick[] =
    "--frame N (counted from 1), or write them all through a name such as out-%04d.png";

// From the input's header, before any pixel is decoded: a 783 KB PNG declaring 16384x16384
// pixels took 4.2 GB to convert.
// `every_frame`: the output holds all the input's frames at once (an FSF or GIF animation).
// `written`: the output's format, or none for a GIF.
void check_convert_memory(const ConvertOptions& options, std::optional<ImageFormat> written,
                          bool every_frame, ExrPixel exr_pixel) {
  const ImageInfo info = read_image_info(options.input);
  MemoryNeed need;
  need.add_read(options.input, info);
  const std::uint64_t frames = every_frame ? info.frames : 1;
  if (written)
    need.add_write(pixels_of(info), frames, reads_as_float(info.format), *written, exr_pixel);
  else
    need.add_gif_write(pixels_of(info), frames, reads_as_float(info.format));
  check_memory(need, "converting " + options.input);
}

// GIF counts delays in hundredths of a second: 25 frames per second is 4 exactly.
int convert_to_gif(const ConvertOptions& options) {
  if (options.format)
    throw UsageError("--format does not apply to a GIF output, which its name chooses");
  // An input no reader takes is a usage error, as below.
  check_display(options, input_format(options.input), false);
  check_convert_memory(options, std::nullopt, !options.frame, ExrPixel::Half);
  AnyImage image = read_any_image(options.input);
  if (options.frame) image = pick_frame(image, options.frame, options.input, kHowToPick);
  const Rgba8Image* rgba = std::get_if<Rgba8Image>(&image);
  const Rgba8Image quantized =
      rgba ? Rgba8Image{} : quantize(std::get<FloatImage>(image), options.display);
  const int delay_cs = static_cast<int>(std::lround(100 / options.fps));
  write_gif(options.output, rgba ? *rgba : quantized, delay_cs);
  return 0;
}

int convert(const ConvertOptions& options) {
  if (is_gif_path(options.output)) return convert_to_gif(options);
  const ImageFormat input = input_format(options.input);
  const bool numbered = is_frame_pattern(options.output);
  // A pattern's first name stands for all of them: they differ in the number alone.
  const ImageOutput output = output_argument(
      numbered ? frame_file_name(options.output, 1) : options.output, options.format);
  check_display(options, input, holds_floats(output.format));
  WriteOptions write_options =
      write_options_for(options.exr_pixel, holds_float32(options.input, input));
  write_options.display = options.display;
  check_convert_memory(options, output.format,
                       output.format == ImageFormat::Fsf && !options.frame && !numbered,
                       write_options.exr_pixel);
  AnyImage image = read_any_image(options.input);
  if (numbered) {
    const int first = options.frame.value_or(1);
    const int last = options.frame.value_or(frame_count(image));
    for (int frame = first; frame <= last; ++frame) {
      const std::string path = frame_file_name(options.output, frame);
      write_converted(path, output_argument(path, options.format),
                      pick_frame(image, frame, options.input, kHowToPick), write_options);
    }
    return 0;
  }
  if (output.format != ImageFormat::Fsf || options.frame)
    image = pick_frame(image, options.frame, options.input, kHowToPick);
  write_converted(options.output, output, image, write_options);
  return 0;
}

}  // namespace

void add_convert(CLI::App& app, Command& command) {
  auto options = std::make_shared<ConvertOptions>();
  CLI::App* sub = app.add_subcommand("convert", "convert an image to another format");
  sub->add_option("input", options->input, "image to read: .fsf .png .ppm .pfm .exr")->required();
  sub->add_option("output", options->output,
                  "image to write, its format by extension or --format (.gif: an animated GIF); - for "
                  "standard output; "
                  "a name with %04d (or %d) writes every frame, one file each: turn-%04d.png")
      ->required();
  add_frame_option(*sub, "--frame", options->frame,
                   "the frame of an animation to convert (default: all into FSF or a %04d "
                   "name; another single-frame output needs it for an animation)");
  add_format_option(*sub, options->format);
  add_exr_pixel_option(*sub, options->exr_pixel);
  sub->add_option("--fps", options->fps,
                  "frames per second of a GIF animation (default 25; GIF keeps hundredths of a "
                  "second, so the delay is rounded to one)")
      ->check(decimal_number(0.1, 100.0));
  sub->add_option("--exposure", options->display.exposure,
                  "float to 8-bit: multiply every value by 2^STOPS first (default 0)")
      ->check(decimal_number());
  sub->add_option_function<std::string>(
         "--tonemap",
         [options](const std::string& name) {
           options->display.curve = *tone_curve_from_name(name);
         },
         "float to 8-bit: the tone curve, clamp (default) or filmic")
      ->transform(word_choice(tone_curve_names()));
  sub->add_flag("--srgb", options->display.srgb,
                "float to 8-bit: encode with sRGB's curve, as clrt --mode path writes its 8-bit "
                "images (default: values as they are, as the Whitted modes write them)");
  sub->callback([&command, options] { command = [options] { return convert(*options); }; });
}

}  // namespace clrt::img
