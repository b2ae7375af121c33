#include "readout.hpp"

#include <cstdio>

namespace clrt::view {
namespace {

std::string picture_name(const ViewNames& names, const ViewState& state) {
  if (state.side_by_side)
    return names.a + " | " + names.b + (state.show_difference ? " | difference" : "");
  if (state.show_difference) return "difference of " + names.a + " and " + names.b;
  return state.flipped == Picture::B ? "B: " + names.b : (names.b.empty() ? "" : "A: ") + names.a;
}

std::string values(const char* label, const FloatImage& image, int x, int y) {
  const float* rgb = &image.rgb[3 * (std::size_t(y) * image.width + x)];
  char text[96];
  std::snprintf(text, sizeof text, " %s %.4g %.4g %.4g", label, static_cast<double>(rgb[0]),
                static_cast<double>(rgb[1]), static_cast<double>(rgb[2]));
  return text;
}

}  // namespace

std::string readout_text(const ViewNames& names, const ViewSources& sources,
                         const ViewState& state, bool playing, std::optional<PixelHit> hit) {
  std::string text = picture_name(names, state);
  if (sources.frame_count() > 1)
    text += " | frame " + std::to_string(state.frame + 1) + "/" +
            std::to_string(sources.frame_count()) + (playing ? "" : " paused");
  char tone[64];
  std::snprintf(tone, sizeof tone, " | exposure %+.1f", state.tone.exposure);
  text += tone;
  if (state.tone.curve == ToneCurve::Filmic) text += " filmic";
  if (state.tone.srgb) {
    text += " sRGB";
  } else {
    std::snprintf(tone, sizeof tone, " gamma %.1f", state.tone.gamma);
    text += tone;
  }
  std::snprintf(tone, sizeof tone, " | zoom %.3gx", state.zoom);
  text += tone;
  if (!hit) return text;
  text += " | (" + std::to_string(hit->x) + ", " + std::to_string(hit->y) + ")";
  text += values("A", ViewSources::frame_of(sources.a, state.frame), hit->x, hit->y);
  if (sources.comparing()) {
    text += values("B", ViewSources::frame_of(sources.b, state.frame), hit->x, hit->y);
    text += values("diff", ViewSources::frame_of(sources.difference, state.frame), hit->x, hit->y);
  }
  return text;
}

}  // namespace clrt::view
