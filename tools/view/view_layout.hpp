// What the window shows and where: one picture (A, B or their difference) or A and B side by
// side (and their difference beside them), each magnified by a whole zoom factor so that every
// image pixel is a square of screen pixels, with a gap between pictures.
#pragma once

#include <optional>
#include <vector>

#include "tone_map.hpp"
#include "view_sources.hpp"

namespace clrt::view {

enum class Picture { A, B, Difference };

struct ViewState {
  ToneSettings tone;
  bool side_by_side = false;    // A | B (| difference): only when comparing
  bool show_difference = false; // the difference alone, or as a third picture side by side
  Picture flipped = Picture::A; // which of A and B shows alone
  int frame = 0;                // counted from 0
  int zoom = 1;
};

struct PicturePlace {
  Picture picture;
  int x = 0, y = 0;  // its top-left corner in the window
};

struct Layout {
  int width = 0, height = 0;  // the window
  int image_width = 0, image_height = 0, zoom = 1;
  std::vector<PicturePlace> places;
};

constexpr int kGap = 2;                 // screen pixels between two pictures
constexpr std::uint32_t kBackground = 0x202020;

// The largest zoom at which `pictures` side by side fit in 1024x768 (at least 1): a 16x12 test
// image opens at 32x, a full HD render at 1x.
int fitting_zoom(int image_width, int image_height, int pictures);

Layout layout_view(const ViewState& state, const ViewSources& sources);

// The image pixel under window point (x, y), and in which picture; nothing over the gaps.
struct PixelHit {
  Picture picture;
  int x = 0, y = 0;
};
std::optional<PixelHit> hit_pixel(const Layout& layout, int x, int y);

// The window's pixels: each picture's frame tone-mapped (the difference as it is, at exposure 0
// and gamma 1: it is already scaled to its largest), the rest the background.
Canvas compose(const Layout& layout, const ViewState& state, const ViewSources& sources);

// The frames of a picture (A, B or the difference).
const std::vector<FloatImage>& frames_of(const ViewSources& sources, Picture picture);

}  // namespace clrt::view
