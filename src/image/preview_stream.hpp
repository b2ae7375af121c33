// What `clrt --preview` sends `clrt-view --preview` while a render fills in. clrt starts the
// viewer with one end of a socket pair as its standard input; both ends run on one machine,
// so every number is in the host's own byte order.
//
//   viewer -> clrt   one byte kPreviewReady once its window is open (or the socket closes:
//                    it could not open one, and said why on its standard error)
//   clrt -> viewer   a PreviewHeader, then for each finished band of pixels a PreviewBand and
//                    its count x 3 floats (linear R, G, B, as rendered); the end of the stream
//                    is the end of the render
//
// Pixels are numbered in row-major order of the region rendered (--pixel-bounds), frame after
// frame of an animation each overwriting the last.
#pragma once

#include <cstdint>

namespace clrt {

constexpr char kPreviewReady = 'R';
constexpr char kPreviewMagic[8] = {'c', 'l', 'r', 't', 'v', 'i', 'e', 'w'};

struct PreviewHeader {
  char magic[8];
  std::uint32_t width, height;
};

struct PreviewBand {
  std::uint64_t first;  // the band's first pixel
  std::uint32_t count;  // its pixels
  std::uint32_t unused; // keeps the floats that follow aligned to 8 bytes, and is 0
};

static_assert(sizeof(PreviewHeader) == 16 && sizeof(PreviewBand) == 16,
              "the stream's records have no padding");

}  // namespace clrt
