// The renderer's own intersect and shadow kernels over a whole ray set, one launch at a time,
// timed by OpenCL profiling events.
#pragma once

#include <vector>

#include "device/device_context.hpp"
#include "geometry/device_geometry.hpp"
#include "host_rays.hpp"

namespace clrt::compare {

// A ray set on the device with room for the kernel's answers.
struct ClrtBatch {
  compute::kernel* kernel;
  compute::buffer rays, results;
  std::size_t count;
  compute::buffer count_on_device;  // the shadow kernel reads its count from the device
};

class ClrtTracer {
 public:
  // `program` is the renderer's program (renderer_program_source()) built on `device`.
  ClrtTracer(DeviceContext& device, const compute::program& program, const GeometryData& geometry);

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
  unsigned first_arg_ = 0;  // the kernels' own arguments follow the SCENE_PARAMS
  compute::buffer params_;
  compute::kernel intersect_, shadow_;
};

}  // namespace clrt::compare
