// Animation on the command line: --frames N renders N frames of a turntable that orbits the
// camera by --orbit DEG in all (default 360); --frame-range A:B renders frames A to B only (1-based,
// inclusive: a farm's share). FSF holds them in one file; other formats get one numbered file per
// frame, name-0001.png.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace clrt {

struct AnimationRequest {
  std::optional<std::uint32_t> frames;
  std::optional<double> orbit_degrees;
  std::optional<std::string> frame_range;  // "A:B"
};

struct FramePlan {
  bool animated = false;      // --frames was given: frames are numbered and the camera orbits
  std::uint32_t frames = 1;   // in the whole animation
  double orbit_degrees = 360;
  std::uint32_t first = 1, last = 1;  // the frames to render, from 1, inclusive
  std::uint32_t count() const { return last - first + 1; }
};

// Throws UsageError for a range outside 1..frames or inverted, or --orbit / --frame-range
// without --frames.
FramePlan resolve_frames(const AnimationRequest& request);

// "dir/name.png" -> "dir/name-0007.png" for frame 7: four digits, more when the animation has
// more frames.
std::string numbered_frame_path(const std::string& path, std::uint32_t frame, std::uint32_t frames);

}  // namespace clrt
