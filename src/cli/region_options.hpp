// --pixel-bounds and --crop-window: the part of the image to render, as pbrt's --pixelbounds
// and --cropwindow take it: four numbers x0,x1,y0,y1 (half-open), in pixels or in fractions of
// the image, as one word with commas or as four words.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "render/pixel_rect.hpp"

namespace clrt {

struct RegionRequest {
  std::optional<std::array<double, 4>> pixel_bounds;  // whole numbers, checked when parsed
  std::optional<std::array<double, 4>> crop_window;   // fractions
};

// "x0,x1,y0,y1" as four numbers; an empty string when fine, else what is wrong. Pixel bounds
// must be whole numbers.
std::string parse_region_numbers(const std::string& text, bool whole,
                                 std::optional<std::array<double, 4>>& out);

// The region for an image of width x height, or none for the whole image. Throws UsageError
// for an empty, inverted or outside region. A crop window maps to pixels [ceil(W x0),
// ceil(W x1)) by [ceil(H y0), ceil(H y1)), as pbrt maps it.
std::optional<PixelRect> resolve_region(const RegionRequest& request, int width, int height);

}  // namespace clrt
