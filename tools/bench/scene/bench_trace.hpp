// Rays for the BVH benchmark (clrt-bench bvh) and their throughput through scene_closest_hit / scene_any_hit.
#pragma once

#include <memory>
#include <vector>

#include "device/device_context.hpp"
#include "geometry/bvh_box.hpp"
#include "device/typed_kernel.hpp"
#include "geometry/bvh_query_args.hpp"
#include "geometry/geometry_data.hpp"

namespace clrt::bench {

// Per ray: origin with w = tmin, then direction with w = tmax.
using RaySet = std::vector<dev::f4>;

// The box of everything but the planes (from the top level's root).
Box scene_bounds(const GeometryData& geometry);

// A camera that sees all of `bounds` from above and in front.
CameraSpec camera_for(const Box& bounds);

// About `count` primary rays of `camera` through the pixel centres of a square image.
RaySet camera_rays(const CameraSpec& camera, int count);

// `count` rays from uniform points of `bounds` in uniform directions.
RaySet random_rays(const Box& bounds, int count);

// Millions of rays per second of elapsed time, and per second of CPU time (per core: steadier
// than elapsed time on a machine shared with other work).
struct Throughput {
  double wall = 0, per_core = 0;
};

class Tracer {
 public:
  Tracer(DeviceContext& device, std::shared_ptr<const GeometryData> geometry);

  // The best of `runs` timed launches after one warm-up launch.
  Throughput closest_hit_mrays(const RaySet& rays, int runs);
  Throughput any_hit_mrays(const RaySet& rays, int runs);

 private:
  template <class Args, class Result>
  Throughput measure(TypedKernel<Args>& kernel, Global<Result> Args::*results, const RaySet& rays,
                     int runs);

  DeviceContext& device_;
  DeviceGeometry geometry_;
  compute::program program_;
  TypedKernel<BvhClosestHitsArgs> closest_;
  TypedKernel<BvhAnyHitsArgs> any_;
  std::size_t local_size_;
};

}  // namespace clrt::bench
