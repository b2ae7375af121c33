// A GeometryData uploaded to one device, and the SCENE_PARAMS arguments
// (kernels/geometry/scene_intersect.h) that every kernel tracing rays takes first.
#pragma once

#include <memory>

#include "device/device_context.hpp"
#include "device/kernel_args.hpp"
#include "geometry/geometry_data.hpp"
#include "shared/bvh.h"
#include "shared/ray.h"
#include "shared/scene.h"

namespace clrt {

CLRT_DEVICE_TYPE_NAME(dev::Instance, "Instance");
CLRT_DEVICE_TYPE_NAME(dev::InstanceMotion, "InstanceMotion");
CLRT_DEVICE_TYPE_NAME(dev::Mesh, "Mesh");
CLRT_DEVICE_TYPE_NAME(dev::Triangle, "Triangle");
CLRT_DEVICE_TYPE_NAME(dev::TriangleNormals, "TriangleNormals");
CLRT_DEVICE_TYPE_NAME(dev::TriangleTexcoords, "TriangleTexcoords");
CLRT_DEVICE_TYPE_NAME(dev::BvhBlock, "BvhBlock");
CLRT_DEVICE_TYPE_NAME(dev::Hit, "Hit");  // what the tracing kernels find

// The SCENE_PARAMS, in their order.
struct SceneArgs {
  cl_uint instance_count = 0;
  cl_uint plane_count = 0;
  Global<const dev::Instance> instances;
  Global<const dev::InstanceMotion> motions;
  Global<const dev::Mesh> meshes;
  Global<const dev::TriangleNormals> triangle_normals;
  Global<const dev::TriangleTexcoords> triangle_texcoords;
  Global<const cl_uint> triangle_materials;
  Global<const dev::BvhBlock> bvh;

  CLRT_KERNEL_ARGS(instance_count, plane_count, instances, motions, meshes, triangle_normals,
                   triangle_texcoords, triangle_materials, bvh)
};

class DeviceGeometry {
 public:
  // On a device that works in host memory the buffers are `tables`' own, kept alive until the
  // runtime has deleted every buffer over them.
  DeviceGeometry(DeviceContext& device, std::shared_ptr<const GeometryData> tables);

  const SceneArgs& args() const { return args_; }
  const GeometryData& tables() const { return *tables_; }

 private:
  std::shared_ptr<const GeometryData> tables_;
  SceneArgs args_;
};

}  // namespace clrt
