#include "cli/animation_options.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>

#include "math/number_fields.hpp"
#include "render/usage_error.hpp"

namespace clrt {

FramePlan resolve_frames(const AnimationRequest& request) {
  FramePlan plan;
  if (!request.frames) {
    if (request.orbit_degrees || request.frame_range)
      throw UsageError("--orbit and --frame-range need --frames N");
    return plan;
  }
  plan.animated = true;
  plan.frames = *request.frames;
  plan.first = 1;
  plan.last = plan.frames;
  if (request.orbit_degrees) plan.orbit_degrees = *request.orbit_degrees;
  if (!std::isfinite(plan.orbit_degrees))
    throw UsageError("--orbit takes a finite number of degrees");
  if (request.frame_range) {
    const auto range = read_number_fields(*request.frame_range, {"#:#", 10});
    if (!range) throw UsageError("--frame-range takes FIRST:LAST, frame numbers from 1, e.g. 1:24");
    const std::uint64_t first = (*range)[0], last = (*range)[1];
    if (first < 1 || last < first || last > plan.frames)
      throw UsageError("--frame-range " + *request.frame_range + ": frames 1 to " +
                       std::to_string(plan.frames) + " exist, and FIRST must not pass LAST");
    plan.first = static_cast<std::uint32_t>(first);
    plan.last = static_cast<std::uint32_t>(last);
  }
  return plan;
}

std::string numbered_frame_path(const std::string& path, std::uint32_t frame, std::uint32_t frames) {
  const std::filesystem::path p(path);
  std::string number = std::to_string(frame);
  const std::size_t digits = std::max<std::size_t>(4, std::to_string(frames).size());
  number.insert(0, digits - std::min(digits, number.size()), '0');
  return (p.parent_path() / (p.stem().string() + "-" + number + p.extension().string())).string();
}

}  // namespace clrt
