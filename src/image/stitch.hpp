// Assembling tiles into their full frame: the image side of farming one frame out in regions.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "image/image.hpp"

namespace clrt {

struct TileImage {
  std::string name;  // for messages, usually the file's path
  AnyImage image;    // a one-frame image; no placement: a whole frame of its own size
};

// What the tiling needs of a tile, which its header gives: its name (for messages), size and
// placement.
struct TileExtent {
  std::string name;
  int width = 0, height = 0;
  std::optional<Placement> placement;  // nothing: a whole frame of its own size
};

struct StitchedFrame {
  int width = 0, height = 0;
};

// The full frame size the tiles make up, before any pixel is read. Throws ImageError unless
// the tiles all belong to one full frame size, within the sides and pixels clrt reads, and
// cover each of its pixels exactly once; an overlap names both tiles and the pixels they share,
// a gap the pixels no tile covers.
StitchedFrame stitched_frame(const std::vector<TileExtent>& tiles);

// The full frame the tiles make up, without a placement: 8-bit when every tile is, float
// otherwise (8-bit tiles as value / 255, which quantises back to the same bytes). Throws
// ImageError, before copying any pixel, as stitched_frame does, or for a tile of more than one
// frame.
AnyImage stitch_tiles(const std::vector<TileImage>& tiles);

}  // namespace clrt
