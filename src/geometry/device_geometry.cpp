#include "geometry/device_geometry.hpp"

#include "device/transfer.hpp"

namespace clrt {

DeviceGeometry::DeviceGeometry(DeviceContext& device, std::shared_ptr<const GeometryData> tables)
    : tables_(std::move(tables)) {
  const GeometryData& g = *tables_;
  args_.instance_count = static_cast<cl_uint>(g.instances.size());
  args_.plane_count = g.plane_count;
  args_.instances = share(device, g.instances, "instance table", tables_);
  args_.motions = share(device, g.motions, "motion table", tables_);
  args_.meshes = share(device, g.meshes, "mesh table", tables_);
  args_.triangle_normals = share(device, g.triangle_normals, "triangle normal table", tables_);
  args_.triangle_texcoords = share(device, g.triangle_texcoords, "triangle texture coordinate table", tables_);
  args_.triangle_materials = share(device, g.triangle_materials, "triangle material table", tables_);
  // The table is stored as nodes but addressed in 64-byte blocks (kernels/shared/bvh.h).
  static_assert(sizeof(dev::BvhNode) % sizeof(dev::BvhBlock) == 0);
  args_.bvh =
      Global<const dev::BvhBlock>(share(device, g.nodes, "BVH node table", tables_).buffer);
}

}  // namespace clrt
