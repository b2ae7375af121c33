// One scene through both tracers: the same ray sets, throughput and agreement for each.
#pragma once

#include <embree3/rtcore.h>

#include <string>
#include <vector>

#include "device/device_context.hpp"

namespace clrt::compare {

struct CompareOptions {
  std::size_t random_rays = 1000000;
  int threads = 2;  // Embree's build and trace threads
  int runs = 5;     // timed runs after one warm-up, the best counts
  RTCBuildQuality quality = RTC_BUILD_QUALITY_HIGH;
  RTCSceneFlags flags = RTC_SCENE_FLAG_NONE;  // or ROBUST: watertight triangles, like clrt's
};

struct Measurement {
  std::string rays;  // camera, random, shadow
  std::size_t count = 0;
  double hit_share = 0;  // clrt's hits (blocked rays for shadow rays)
  double clrt_seconds = 0, embree_seconds = 0;
  double agreement = 0;
  std::vector<std::string> disagreements;  // the first few rays they disagree on, described
};

struct SceneResult {
  std::string name, primitives;
  std::string skipped;  // why, when Embree cannot be given the scene
  double clrt_build_seconds = 0, embree_build_seconds = 0;
  std::vector<Measurement> sets;
};

// `program` is the renderer's program built on `device`. Progress goes to stderr.
SceneResult compare_scene(const std::string& path, DeviceContext& device,
                          const compute::program& program, const CompareOptions& options);

}  // namespace clrt::compare
