// What the window shows and where: one picture (A, B or their difference) or A and B side by
// side (and their difference beside them), with a gap between pictures, each scaled by any zoom
// factor: magnified, every image pixel is a block of screen pixels (a square at a whole zoom);
// reduced, every screen pixel is the mean of the image pixels it covers.
#pragma once

#include <optional>
#include <vector>

#include "tone_map.hpp"
#include "view_sources.hpp"

namespace clrt::view {

enum class Picture { A, B, Difference };

// The part of the screen a window may take (the display's usable bounds).
struct ScreenArea {
  int width = 1024, height = 768;
};

struct ViewState {
  ToneSettings tone;
  bool side_by_side = false;    // A | B (| difference): only when comparing
  bool show_difference = false; // the difference alone, or as a third picture side by side
  Picture flipped = Picture::A; // which of A and B shows alone
  int frame = 0;                // counted from 0
  double zoom = 1;              // screen pixels per image pixel, along each axis
  ScreenArea screen;            // what the window must fit in
};

struct PicturePlace {
  Picture picture;
  int x = 0, y = 0;  // its top-left corner in the window
};

struct Layout {
  int width = 0, height = 0;  // the window
  int image_width = 0, image_height = 0;
  int picture_width = 0, picture_height = 0;  // screen pixels of each picture
  double zoom = 1;
  std::vector<PicturePlace> places;
};

constexpr int kGap = 2;                 // screen pixels between two pictures
constexpr std::uint32_t kBackground = 0x202020;
constexpr double kMinZoom = 1.0 / 64, kMaxZoom = 256;
constexpr ScreenArea kFirstWindow{1024, 768};  // the most a magnified first window takes
// Room left on the screen for a window manager's frame and title bar, which SDL cannot measure
// before a window exists: the window fits the display's usable bounds less this.
constexpr ScreenArea kWindowFrame{16, 64};

// The zoom a window opens at: the largest whole zoom at which `pictures` side by side fit the
// smaller of 1024x768 and `screen` (a 16x12 test image opens at 64x); pictures that do not fit
// the screen at 1x are reduced by the factor that fits them exactly (a 4K render on a full HD
// screen: about 0.49x).
double fitting_zoom(int image_width, int image_height, int pictures, ScreenArea screen);

// The zoom the keys step to, in and out: the whole numbers above 1 and their reciprocals below
// it (..., 1/3, 1/2, 1, 2, 3, ...); a zoom between two steps goes to the nearer one that way.
double zoom_in(double zoom);
double zoom_out(double zoom);

// fitting_zoom() for the pictures `state` shows, on its screen.
double zoom_to_fit(const ViewState& state, const ViewSources& sources);

// Lowers the zoom just enough that what `state` shows fits its screen (after a key showed more
// pictures side by side); a view that fits is left as it is.
void keep_on_screen(ViewState& state, const ViewSources& sources);

Layout layout_view(const ViewState& state, const ViewSources& sources);

// The image pixel under window point (x, y), and in which picture; nothing over the gaps.
struct PixelHit {
  Picture picture;
  int x = 0, y = 0;
};
std::optional<PixelHit> hit_pixel(const Layout& layout, int x, int y);

// The window's pixels: each picture's frame tone-mapped (the difference as it is, at exposure 0
// and gamma 1: it is already scaled to its largest), the rest the background. A reduced
// picture's screen pixel tone-maps the mean of the radiance it covers, not the mean of displayed
// bytes, so that a reduced render is as bright as the render.
Canvas compose(const Layout& layout, const ViewState& state, const ViewSources& sources);

// The frames of a picture (A, B or the difference).
const std::vector<FloatImage>& frames_of(const ViewSources& sources, Picture picture);

}  // namespace clrt::view
