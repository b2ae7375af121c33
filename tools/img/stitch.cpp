// clrt-img stitch OUT TILES...: the full frame from tiles that record their placement (PNG,
// EXR), after checking that they cover it exactly once.
#include <algorithm>
#include <memory>
#include <vector>

#include "command_line.hpp"
#include "image/image_info.hpp"
#include "image/stitch.hpp"
#include "memory_need.hpp"

namespace clrt::img {
namespace {

struct StitchOptions {
  std::string output;
  std::vector<std::string> tiles;
  std::optional<ImageFormat> format;
  std::optional<ExrPixel> exr_pixel;
};

// The frame's size and the memory the whole stitch takes, from the tiles' headers: two tiles of
// 783 KB each could declare a frame beyond what clrt reads, or gigabytes of pixels.
void check_stitch_before_reading(const StitchOptions& options, const ImageOutput& output) {
  std::vector<TileExtent> extents;
  std::vector<ImageInfo> infos;
  for (const std::string& path : options.tiles) {
    infos.push_back(read_image_info(path));
    extents.push_back({path, infos.back().width, infos.back().height, infos.back().placement});
  }
  const StitchedFrame frame = stitched_frame(extents);
  const bool float_frame = std::any_of(infos.begin(), infos.end(), [](const ImageInfo& info) {
    return reads_as_float(info.format);
  });
  MemoryNeed need;
  std::uint64_t largest_8bit_tile = 0;
  for (std::size_t i = 0; i < infos.size(); ++i) {
    need.add_read(options.tiles[i], infos[i]);
    if (!reads_as_float(infos[i].format))
      largest_8bit_tile = std::max(largest_8bit_tile, pixels_of(infos[i]));
  }
  // Into a float frame, each 8-bit tile is copied as floats first.
  if (float_frame) need.add_pixels(largest_8bit_tile, 1, 12);
  const std::uint64_t frame_pixels = static_cast<std::uint64_t>(frame.width) * frame.height;
  need.add_pixels(frame_pixels, 1, float_frame ? 12 : 4);
  const bool float32 = std::any_of(infos.begin(), infos.end(),
                                   [](const ImageInfo& info) { return info.float32; });
  need.add_write(frame_pixels, 1, float_frame, output.format,
                 exr_pixel_for(options.exr_pixel, float32));
  check_memory(need, "stitching " + std::to_string(infos.size()) + " tiles into their " +
                         std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                         " frame");
}

int stitch(const StitchOptions& options) {
  const ImageOutput output = output_argument(options.output, options.format);
  std::vector<ImageFormat> formats;
  for (const std::string& path : options.tiles) {
    formats.push_back(input_format(path));
    if (!records_placement(formats.back()))
      throw UsageError(path + ": " + format_name(formats.back()) +
                       " cannot record where a tile belongs; write tiles as PNG or EXR");
  }
  check_stitch_before_reading(options, output);
  std::vector<TileImage> tiles;
  bool float32 = false;
  for (std::size_t i = 0; i < options.tiles.size(); ++i) {
    tiles.push_back({options.tiles[i], read_any_image(options.tiles[i])});
    float32 = float32 || holds_float32(options.tiles[i], formats[i]);
  }
  const WriteOptions write_options = write_options_for(options.exr_pixel, float32);
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
