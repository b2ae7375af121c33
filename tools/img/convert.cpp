// clrt-img convert IN OUT: any format clrt reads into any it writes. 8-bit to 8-bit and float
// to float keep every value; float to 8-bit quantises as clrt does; 8-bit to float gives
// value / 255. All frames of an FSF go into an FSF; other outputs take the frame --frame names.
#include <memory>

#include "command_line.hpp"
#include "image/image_info.hpp"

namespace clrt::img {
namespace {

struct ConvertOptions {
  std::string input, output;
  std::optional<int> frame;
  std::optional<ImageFormat> format;
  std::optional<ExrPixel> exr_pixel;
};

int convert(const ConvertOptions& options) {
  const ImageFormat input = input_format(options.input);
  const ImageOutput output = output_argument(options.output, options.format);
  AnyImage image = read_any_image(options.input);
  if (output.format != ImageFormat::Fsf || options.frame)
    image = pick_frame(std::move(image), options.frame, options.input);
  const std::optional<Placement> placement =
      std::visit([](const auto& i) { return i.placement; }, image);
  if (placement && !records_placement(output.format))
    warn(options.output + ": " + format_name(output.format) +
         " cannot record the placement; only the tile's pixels are written");
  const WriteOptions write_options{
      exr_pixel_for(options.exr_pixel, holds_float32(options.input, input))};
  std::visit([&](const auto& i) { write_image(output, i, write_options); }, image);
  return 0;
}

}  // namespace

void add_convert(CLI::App& app, Command& command) {
  auto options = std::make_shared<ConvertOptions>();
  CLI::App* sub = app.add_subcommand("convert", "convert an image to another format");
  sub->add_option("input", options->input, "image to read: .fsf .png .ppm .pfm .exr")->required();
  sub->add_option("output", options->output,
                  "image to write, its format by extension or --format; - for standard output")
      ->required();
  add_frame_option(*sub, options->frame,
                   "the frame of an animation to convert (default: all into FSF; a single-frame "
                   "output needs it for an animation)");
  add_format_option(*sub, options->format);
  add_exr_pixel_option(*sub, options->exr_pixel);
  sub->callback([&command, options] { command = [options] { return convert(*options); }; });
}

}  // namespace clrt::img
