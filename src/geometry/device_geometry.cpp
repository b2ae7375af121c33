#include "geometry/device_geometry.hpp"

#include "device/transfer.hpp"

namespace clrt {

DeviceGeometry::DeviceGeometry(DeviceContext& device, const GeometryData& geometry) {
  args_.instance_count = static_cast<cl_uint>(geometry.instances.size());
  args_.plane_count = geometry.plane_count;
  args_.instances = share(device, geometry.instances, "instance table");
  args_.meshes = share(device, geometry.meshes, "mesh table");
  args_.triangle_normals = share(device, geometry.triangle_normals, "triangle normal table");
  args_.triangle_materials = share(device, geometry.triangle_materials, "triangle material table");
  // The table is stored as nodes but addressed in 64-byte blocks (kernels/shared/bvh.h).
  static_assert(sizeof(dev::BvhNode) % sizeof(dev::BvhBlock) == 0);
  args_.bvh = Global<const dev::BvhBlock>(share(device, geometry.nodes, "BVH node table").buffer);
}

}  // namespace clrt
