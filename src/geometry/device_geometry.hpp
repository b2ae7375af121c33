// A GeometryData uploaded to one device, bound to kernels as the SCENE_PARAMS arguments of
// kernels/geometry/scene_intersect.h.
#pragma once

#include "device/device_context.hpp"
#include "geometry/geometry_data.hpp"

namespace clrt {

class DeviceGeometry {
 public:
  DeviceGeometry(DeviceContext& device, const GeometryData& geometry);

  // Sets the SCENE_PARAMS arguments of `kernel`, in order, starting at `first_arg`; returns the
  // index of the kernel's next argument.
  unsigned bind(compute::kernel& kernel, unsigned first_arg) const;

 private:
  dev::u32 instance_count_;
  dev::u32 plane_count_;
  compute::buffer instances_;
  compute::buffer meshes_;
  compute::buffer triangle_normals_;
  compute::buffer triangle_materials_;
  compute::buffer nodes_;
};

}  // namespace clrt
