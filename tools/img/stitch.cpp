// clrt-img stitch OUT TILES...: the full frame from tiles that record their placement (PNG,
// EXR), after checking that they cover it exactly once.
#include <memory>
#include <vector>

#include "command_line.hpp"
#include "image/image_info.hpp"
#include "image/stitch.hpp"

namespace clrt::img {
namespace {

struct StitchOptions {
  std::string output;
  std::vector<std::string> tiles;
  std::optional<ImageFormat> format;
  std::optional<ExrPixel> exr_pixel;
};

int stitch(const StitchOptions& options) {
  const ImageOutput output = output_argument(options.output, options.format);
  std::vector<ImageFormat> formats;
  for (const std::string& path : options.tiles) {
    formats.push_back(input_format(path));
    if (!records_placement(formats.back()))
      throw UsageError(path + ": " + format_name(formats.back()) +
                       " cannot record where a tile belongs; write tiles as PNG or EXR");
  }
  std::vector<TileImage> tiles;
  bool float32 = false;
  for (std::size_t i = 0; i < options.tiles.size(); ++i) {
    tiles.push_back({options.tiles[i], read_any_image(options.tiles[i])});
    float32 = float32 || holds_float32(options.tiles[i], formats[i]);
  }
  const WriteOptions write_options{exr_pixel_for(options.exr_pixel, float32)};
  std::visit([&](const auto& image) { write_image(output, image, write_options); },
             stitch_tiles(tiles));
  return 0;
}

}  // namespace

void add_stitch(CLI::App& app, Command& command) {
  auto options = std::make_shared<StitchOptions>();
  CLI::App* sub = app.add_subcommand(
      "stitch", "assemble PNG or EXR tiles into their full frame, each pixel covered once");
  sub->add_option("output", options->output,
                  "the full image, its format by extension or --format; - for standard output")
      ->required();
  sub->add_option("tiles", options->tiles, "the tiles: .png or .exr files")->required();
  add_format_option(*sub, options->format);
  add_exr_pixel_option(*sub, options->exr_pixel);
  sub->callback([&command, options] { command = [options] { return stitch(*options); }; });
}

}  // namespace clrt::img
