#include "view_layout.hpp"

#include <algorithm>

namespace clrt::view {

int fitting_zoom(int image_width, int image_height, int pictures) {
  const int across = pictures * image_width + (pictures - 1) * kGap;
  return std::max(1, std::min(1024 / std::max(across, 1), 768 / std::max(image_height, 1)));
}

namespace {

std::vector<Picture> pictures_shown(const ViewState& state, const ViewSources& sources) {
  if (!sources.comparing()) return {Picture::A};
  if (state.side_by_side) {
    if (state.show_difference) return {Picture::A, Picture::B, Picture::Difference};
    return {Picture::A, Picture::B};
  }
  return {state.show_difference ? Picture::Difference : state.flipped};
}

}  // namespace

Layout layout_view(const ViewState& state, const ViewSources& sources) {
  Layout layout;
  layout.image_width = sources.width;
  layout.image_height = sources.height;
  layout.zoom = state.zoom;
  const int picture_width = sources.width * state.zoom;
  int x = 0;
  for (Picture picture : pictures_shown(state, sources)) {
    if (x > 0) x += kGap;
    layout.places.push_back({picture, x, 0});
    x += picture_width;
  }
  layout.width = x;
  layout.height = sources.height * state.zoom;
  return layout;
}

std::optional<PixelHit> hit_pixel(const Layout& layout, int x, int y) {
  if (y < 0 || y >= layout.height) return std::nullopt;
  for (const PicturePlace& place : layout.places) {
    const int px = x - place.x;
    if (px >= 0 && px < layout.image_width * layout.zoom)
      return PixelHit{place.picture, px / layout.zoom, (y - place.y) / layout.zoom};
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
  const int zoom = layout.zoom;
  for (const PicturePlace& place : layout.places) {
    const FloatImage& image = ViewSources::frame_of(frames_of(sources, place.picture), state.frame);
    const ToneSettings tone = place.picture == Picture::Difference ? ToneSettings{} : state.tone;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const std::uint32_t pixel =
            tone_map_pixel(&image.rgb[3 * (std::size_t(y) * image.width + x)], tone);
        for (int dy = 0; dy < zoom; ++dy) {
          std::uint32_t* row =
              &canvas.pixels[std::size_t(place.y + y * zoom + dy) * canvas.width + place.x];
          std::fill(row + x * zoom, row + (x + 1) * zoom, pixel);
        }
      }
  }
  return canvas;
}

}  // namespace clrt::view
