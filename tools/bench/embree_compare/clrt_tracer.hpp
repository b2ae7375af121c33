// The renderer's own intersect and shadow kernels over a whole ray set, one launch at a time,
// timed by OpenCL profiling events.
#pragma once

#include <vector>

#include "device/device_context.hpp"
#include "device/typed_kernel.hpp"
#include "geometry/device_geometry.hpp"
#include "render/stage_args.hpp"
#include "host_rays.hpp"

namespace clrt::compare {

// A ray set on the device with room for the kernel's answers: the arguments of intersect (a
// closest-hit batch) or of shadow (an occlusion batch).
struct ClrtBatch {
  bool occlusion = false;
  IntersectArgs closest;
  ShadowArgs shadow;
  std::size_t count = 0;
};

class ClrtTracer {
 public:
  // `program` is the renderer's program (renderer_program_source()) built on `device`. The tracer
  // keeps `geometry`: a CPU device reads its tables where they lie.
  ClrtTracer(DeviceContext& device, const compute::program& program, GeometryData geometry);

  // For scene_closest_hit of every ray (intersect.cl).
  ClrtBatch closest_batch(const RaySet& set);
  // For scene_any_hit of every ray up to its tmax (shadow.cl).
  ClrtBatch occlusion_batch(const RaySet& set);

  // One launch over the whole batch; the device's seconds from start to end.
  double launch(ClrtBatch& batch);

  std::vector<dev::Hit> hits(const ClrtBatch& closest);
  std::vector<char> blocked(const ClrtBatch& occlusion);  // 1 where blocked

 private:
  DeviceContext& device_;
  DeviceGeometry geometry_;
  Global<const dev::RenderParams> params_;
  TypedKernel<IntersectArgs> intersect_;
  TypedKernel<ShadowArgs> shadow_;
  std::size_t local_size_;
};

}  // namespace clrt::compare
