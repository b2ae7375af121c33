// Assembling tiles into their full frame: the image side of farming one frame out in regions.
#pragma once

#include <string>
#include <vector>

#include "image/image.hpp"

namespace clrt {

struct TileImage {
  std::string name;  // for messages, usually the file's path
  AnyImage image;    // a one-frame image; no placement: a whole frame of its own size
};

// The full frame the tiles make up, without a placement: 8-bit when every tile is, float
// otherwise (8-bit tiles as value / 255, which quantises back to the same bytes). Throws
// ImageError, before copying any pixel, unless the tiles all belong to one full frame size and
// cover each of its pixels exactly once; an overlap names both tiles and the pixels they share,
// a gap the pixels no tile covers.
AnyImage stitch_tiles(const std::vector<TileImage>& tiles);

}  // namespace clrt
