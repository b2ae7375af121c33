// A placement as text (PNG's text chunk, `clrt-img info`) and the checks every placement passes.
#pragma once

#include <optional>
#include <string>

#include "image/image.hpp"

namespace clrt::image_detail {

// The PNG tEXt keyword clrt records a placement under.
constexpr const char* kPngPlacementKey = "clrt:placement";

// "X,Y WxH of FULL_WxFULL_H", e.g. "64,0 64x32 of 256x128": the tile's top-left pixel, its size
// and the full frame's size, decimal, single spaces.
std::string placement_text(const Placement& placement, int width, int height);
// The exact inverse of placement_text for an image of width x height; ImageError (prefixed with
// `context`) for any other text, a size other than the image's, or a region outside the frame.
Placement parse_placement_text(const std::string& text, int width, int height,
                               const std::string& context);

// Throws ImageError("<context>: ...") unless a width x height image at `placement` lies inside
// its frame.
void check_placement(const Placement& placement, int width, int height,
                     const std::string& context);

// What a file records: nothing for an image that is its whole frame.
std::optional<Placement> recorded_placement(const std::optional<Placement>& placement, int width,
                                            int height);

}  // namespace clrt::image_detail
