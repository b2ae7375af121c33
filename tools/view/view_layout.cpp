#include "view_layout.hpp"

#include <algorithm>
#include <cmath>

namespace clrt::view {
namespace {

// A zoom's screen pixels for `image` pixels: at least one.
int scaled(int image, double zoom) {
  return std::max(1, static_cast<int>(std::floor(image * zoom + 1e-9)));
}

// The image pixels [first, end) under screen pixel `screen` of a picture scaled by `zoom`: one
// when magnified, all those it covers when reduced.
struct Span {
  int first, end;
};
Span image_span(int screen, double zoom, int image) {
  const int first = std::min(image - 1, static_cast<int>(std::floor(screen / zoom + 1e-9)));
  const int end = std::min(image, static_cast<int>(std::floor((screen + 1) / zoom + 1e-9)));
  return {first, std::max(first + 1, end)};
}

std::vector<Picture> pictures_shown(const ViewState& state, const ViewSources& sources) {
  if (!sources.comparing()) return {Picture::A};
  if (state.side_by_side) {
    if (state.show_difference) return {Picture::A, Picture::B, Picture::Difference};
    return {Picture::A, Picture::B};
  }
  return {state.show_difference ? Picture::Difference : state.flipped};
}

bool fits(const Layout& layout, ScreenArea screen) {
  return layout.width <= screen.width && layout.height <= screen.height;
}

}  // namespace

double fitting_zoom(int image_width, int image_height, int pictures, ScreenArea screen) {
  const int gaps = (pictures - 1) * kGap;
  const int across = pictures * std::max(image_width, 1), down = std::max(image_height, 1);
  const ScreenArea first{std::min(screen.width, kFirstWindow.width),
                         std::min(screen.height, kFirstWindow.height)};
  const int whole = std::min((first.width - gaps) / across, first.height / down);
  if (whole >= 1) return std::min<double>(whole, kMaxZoom);
  const double fraction = std::min(double(screen.width - gaps) / across, double(screen.height) / down);
  return std::clamp(fraction, kMinZoom, 1.0);
}

double zoom_in(double zoom) {
  if (zoom >= 1) return std::min(kMaxZoom, std::floor(zoom + 1e-9) + 1);
  return 1 / (std::ceil(1 / zoom - 1e-9) - 1);
}

double zoom_out(double zoom) {
  if (zoom > 1) return std::ceil(zoom - 1e-9) - 1;
  return std::max(kMinZoom, 1 / (std::floor(1 / zoom + 1e-9) + 1));
}

double zoom_to_fit(const ViewState& state, const ViewSources& sources) {
  const int pictures = static_cast<int>(pictures_shown(state, sources).size());
  return fitting_zoom(sources.width, sources.height, pictures, state.screen);
}

void keep_on_screen(ViewState& state, const ViewSources& sources) {
  if (!fits(layout_view(state, sources), state.screen))
    state.zoom = std::min(state.zoom, zoom_to_fit(state, sources));
}

Layout layout_view(const ViewState& state, const ViewSources& sources) {
  Layout layout;
  layout.image_width = sources.width;
  layout.image_height = sources.height;
  layout.zoom = state.zoom;
  layout.picture_width = scaled(sources.width, state.zoom);
  layout.picture_height = scaled(sources.height, state.zoom);
  int x = 0;
  for (Picture picture : pictures_shown(state, sources)) {
    if (x > 0) x += kGap;
    layout.places.push_back({picture, x, 0});
    x += layout.picture_width;
  }
  layout.width = x;
  layout.height = layout.picture_height;
  return layout;
}

std::optional<PixelHit> hit_pixel(const Layout& layout, int x, int y) {
  if (y < 0 || y >= layout.height) return std::nullopt;
  for (const PicturePlace& place : layout.places) {
    const int px = x - place.x;
    if (px >= 0 && px < layout.picture_width)
      return PixelHit{place.picture, image_span(px, layout.zoom, layout.image_width).first,
                      image_span(y - place.y, layout.zoom, layout.image_height).first};
  }
  return std::nullopt;
}

const std::vector<FloatImage>& frames_of(const ViewSources& sources, Picture picture) {
  switch (picture) {
    case Picture::A: return sources.a;
    case Picture::B: return sources.b;
    case Picture::Difference: break;
  }
  return sources.difference;
}

Canvas compose(const Layout& layout, const ViewState& state, const ViewSources& sources) {
  Canvas canvas{layout.width, layout.height,
                std::vector<std::uint32_t>(std::size_t(layout.width) * layout.height, kBackground)};
  // Each screen column's and row's image pixels, worked out once for every picture.
  std::vector<Span> columns, rows;
  for (int x = 0; x < layout.picture_width; ++x)
    columns.push_back(image_span(x, layout.zoom, layout.image_width));
  for (int y = 0; y < layout.picture_height; ++y)
    rows.push_back(image_span(y, layout.zoom, layout.image_height));
  for (const PicturePlace& place : layout.places) {
    const FloatImage& image = ViewSources::frame_of(frames_of(sources, place.picture), state.frame);
    const ToneSettings tone = place.picture == Picture::Difference ? ToneSettings{} : state.tone;
    for (int y = 0; y < layout.picture_height; ++y) {
      std::uint32_t* row = &canvas.pixels[std::size_t(place.y + y) * canvas.width + place.x];
      for (int x = 0; x < layout.picture_width; ++x) {
        const Span across = columns[std::size_t(x)], down = rows[std::size_t(y)];
        float mean[3] = {0, 0, 0};
        for (int iy = down.first; iy < down.end; ++iy)
          for (int ix = across.first; ix < across.end; ++ix)
            for (int c = 0; c < 3; ++c) mean[c] += image.rgb[3 * (std::size_t(iy) * image.width + ix) + c];
        const float count = float((down.end - down.first) * (across.end - across.first));
        for (float& channel : mean) channel /= count;
        row[x] = tone_map_pixel(mean, tone);
      }
    }
  }
  return canvas;
}

}  // namespace clrt::view
