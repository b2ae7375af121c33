#include "controls.hpp"

#include <cmath>

namespace clrt::view {

int Playback::advance(int frame, int count, double seconds) {
  if (!playing || count < 2) return frame;
  carried += seconds;
  const double period = 1 / fps;
  const auto steps = static_cast<long long>(std::floor(carried / period));
  carried -= static_cast<double>(steps) * period;
  return static_cast<int>((frame + steps) % count);
}

bool apply_key(Key key, ViewState& state, Playback& playback, const ViewSources& sources) {
  const int count = sources.frame_count();
  switch (key) {
    case Key::ExposureUp: state.tone.exposure += kExposureStep; break;
    case Key::ExposureDown: state.tone.exposure -= kExposureStep; break;
    case Key::ExposureReset: state.tone = {}; break;
    case Key::Gamma:
      // sRGB's encoding would hide the gamma: off, so that the key always shows its change.
      state.tone.gamma = state.tone.gamma == 1 ? kDisplayGamma : 1;
      state.tone.srgb = false;
      break;
    case Key::Srgb: state.tone.srgb = !state.tone.srgb; break;
    case Key::Filmic:
      state.tone.curve =
          state.tone.curve == ToneCurve::Filmic ? ToneCurve::Clamp : ToneCurve::Filmic;
      break;
    case Key::PlayPause:
      playback.playing = !playback.playing;
      playback.carried = 0;
      break;
    case Key::NextFrame:
    case Key::PreviousFrame:
      playback.playing = false;
      state.frame = (state.frame + (key == Key::NextFrame ? 1 : count - 1)) % count;
      break;
    case Key::Flip:
      if (sources.comparing()) state.flipped = state.flipped == Picture::A ? Picture::B : Picture::A;
      break;
    case Key::Difference:
      if (sources.comparing()) state.show_difference = !state.show_difference;
      keep_on_screen(state, sources);
      break;
    case Key::SideBySide:
      if (sources.comparing()) state.side_by_side = !state.side_by_side;
      keep_on_screen(state, sources);
      break;
    case Key::ZoomIn: state.zoom = zoom_in(state.zoom); break;
    case Key::ZoomOut: state.zoom = zoom_out(state.zoom); break;
    case Key::ZoomToFit: state.zoom = zoom_to_fit(state, sources); break;
    case Key::Quit: return false;
  }
  return true;
}

}  // namespace clrt::view
