// As long a side and as many pixels as clrt renders (scene/limits.hpp), in any image it reads
// or assembles: a header of a few bytes may declare any size, and the size decides what is
// allocated before a pixel is decoded.
#pragma once

#include <cstdint>

namespace clrt::image_detail {

constexpr std::int64_t kMostSide = 65536;
constexpr std::int64_t kMostPixels = std::int64_t{1} << 28;

inline bool within_image_limits(std::int64_t width, std::int64_t height) {
  return width <= kMostSide && height <= kMostSide && width * height <= kMostPixels;
}

}  // namespace clrt::image_detail
