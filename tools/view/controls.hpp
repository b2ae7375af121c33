// What the keys do and how an animation plays: plain functions, so the tests can drive them
// without a window (window.cpp maps SDL's keys onto Key).
#pragma once

#include "view_layout.hpp"

namespace clrt::view {

enum class Key {
  ExposureUp,    // + or =
  ExposureDown,  // -
  ExposureReset, // 0: exposure 0, gamma 1, no curve, no sRGB
  Gamma,         // g: gamma 1 <-> 2.2, sRGB off
  Srgb,          // e: sRGB's encoding on / off
  Filmic,        // f: the filmic curve on / off
  PlayPause,     // space
  NextFrame,     // right
  PreviousFrame, // left
  Flip,          // tab: A <-> B
  Difference,    // d
  SideBySide,    // s
  ZoomIn,        // ]
  ZoomOut,       // [
  ZoomToFit,     // z: the zoom the window opened at, for what it shows now
  Quit,          // q or escape
};

constexpr double kExposureStep = 0.5;  // stops a key press adds or takes
constexpr double kDisplayGamma = 2.2;

// Frames advance at `fps` while playing; a step by hand pauses.
struct Playback {
  double fps = 25;
  bool playing = true;
  double carried = 0;  // seconds since the frame shown became due
  // The frame after `seconds` more of playing from `frame` of `count`, looping.
  int advance(int frame, int count, double seconds);
};

// Applies `key`; false when it asks to quit.
bool apply_key(Key key, ViewState& state, Playback& playback, const ViewSources& sources);

}  // namespace clrt::view
