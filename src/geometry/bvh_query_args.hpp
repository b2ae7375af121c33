// The arguments of the plain ray-query kernels of kernels/geometry/bvh_query_kernels.h, which the
// BVH tests and benchmarks build into programs of their own. Ray i is rays[2i] = origin with
// w = tmin, rays[2i + 1] = direction with w = tmax.
#pragma once

#include "geometry/device_geometry.hpp"

namespace clrt {

struct BvhClosestHitsArgs {
  static constexpr const char* kName = "bvh_closest_hits";
  SceneArgs scene;
  Global<const dev::f4> rays;
  cl_uint count = 0;
  Global<dev::Hit> hits;
  CLRT_KERNEL_ARGS(scene, rays, count, hits)
};

struct BvhAnyHitsArgs {
  static constexpr const char* kName = "bvh_any_hits";
  SceneArgs scene;
  Global<const dev::f4> rays;
  cl_uint count = 0;
  Global<cl_int> results;  // 1 where the ray has a hit
  CLRT_KERNEL_ARGS(scene, rays, count, results)
};

}  // namespace clrt
