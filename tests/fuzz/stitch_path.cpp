#include <cstdio>
#include <fstream>

#include "fuzz_input_file.hpp"
#include "fuzz_paths.hpp"
#include "fuzz_require.hpp"
#include "image/image.hpp"
#include "image/image_info.hpp"
#include "image/placement.hpp"
#include "image/stitch.hpp"

namespace clrt::fuzz {
namespace {

// Few and small tiles: what is fuzzed is their placement, not their size.
constexpr std::size_t kMostTiles = 8;
constexpr int kLongestSide = 32;

// Each pixel names its tile and its place in it, so a misplaced one is seen.
Rgba8Image numbered_tile(std::size_t tile, int width, int height) {
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      rgba.insert(rgba.end(), {static_cast<std::uint8_t>(tile), static_cast<std::uint8_t>(x),
                               static_cast<std::uint8_t>(y), 255});
  return Rgba8Image(width, height, {std::move(rgba)});
}

}  // namespace

Outcome stitch_tiles(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> tile_paths;
  std::vector<Rgba8Image> written;
  try {
    for (std::string line; std::getline(in, line) && written.size() < kMostTiles;) {
      int width = 0, height = 0;
      if (std::sscanf(line.c_str(), "%*d,%*d %dx%d", &width, &height) != 2 || width < 1 ||
          height < 1 || width > kLongestSide || height > kLongestSide)
        return Outcome::Rejected;
      Rgba8Image tile = numbered_tile(written.size(), width, height);
      tile.placement = image_detail::parse_placement_text(line, width, height, "the tile");
      tile_paths.push_back(input_dir() + "/tile-" + std::to_string(written.size()) + ".png");
      write_image(tile_paths.back(), tile);
      written.push_back(std::move(tile));
    }
    // As clrt-img stitch does: the frame from the headers, then the pixels.
    std::vector<TileExtent> extents;
    for (const std::string& tile : tile_paths) {
      const ImageInfo info = read_image_info(tile);
      extents.push_back({tile, info.width, info.height, info.placement});
    }
    stitched_frame(extents);
    std::vector<TileImage> tiles;
    for (const std::string& tile : tile_paths) tiles.push_back({tile, read_any_image(tile)});
    const Rgba8Image frame = std::get<Rgba8Image>(clrt::stitch_tiles(tiles));
    for (const Rgba8Image& tile : written) {
      const Placement at =
          tile.placement.value_or(Placement{0, 0, tile.width, tile.height});
      for (int y = 0; y < tile.height; ++y)
        for (int x = 0; x < tile.width; ++x)
          for (std::size_t c = 0; c < 4; ++c)
            require(frame.frames.front()[4 * (static_cast<std::size_t>(at.y + y) * frame.width +
                                              static_cast<std::size_t>(at.x + x)) + c] ==
                        tile.frames.front()[4 * (static_cast<std::size_t>(y) * tile.width +
                                                 static_cast<std::size_t>(x)) + c],
                    "a stitched pixel is not its tile's");
    }
  } catch (const ImageError&) {
    return Outcome::Rejected;
  }
  return Outcome::Accepted;
}

}  // namespace clrt::fuzz
