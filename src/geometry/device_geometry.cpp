#include "geometry/device_geometry.hpp"

#include <string>
#include <vector>

namespace clrt {
namespace {

template <class T>
compute::buffer upload(DeviceContext& device, const std::vector<T>& table, const std::string& what) {
  compute::buffer buffer = device.allocate(sizeof(T) * table.size(), what);
  if (!table.empty())
    device.queue().enqueue_write_buffer(buffer, 0, sizeof(T) * table.size(), table.data());
  return buffer;
}

}  // namespace

DeviceGeometry::DeviceGeometry(DeviceContext& device, const GeometryData& geometry)
    : instance_count_(static_cast<dev::u32>(geometry.instances.size())),
      plane_count_(geometry.plane_count),
      instances_(upload(device, geometry.instances, "instance table")),
      meshes_(upload(device, geometry.meshes, "mesh table")),
      triangle_normals_(upload(device, geometry.triangle_normals, "triangle normal table")),
      triangle_materials_(upload(device, geometry.triangle_materials, "triangle material table")),
      nodes_(upload(device, geometry.nodes, "BVH node table")) {}

unsigned DeviceGeometry::bind(compute::kernel& kernel, unsigned first_arg) const {
  unsigned a = first_arg;
  kernel.set_arg(a++, instance_count_);
  kernel.set_arg(a++, plane_count_);
  kernel.set_arg(a++, instances_);
  kernel.set_arg(a++, meshes_);
  kernel.set_arg(a++, triangle_normals_);
  kernel.set_arg(a++, triangle_materials_);
  kernel.set_arg(a++, nodes_);
  return a;
}

}  // namespace clrt
