#include "geometry/geometry_data.hpp"

#include "geometry/bvh_scene.hpp"
#include "geometry/instance_table.hpp"
#include "geometry/mesh_table.hpp"

namespace clrt {
namespace {

template <class T>
std::size_t bytes(const std::vector<T>& table) {
  return sizeof(T) * table.size();
}

void append_instances(const Scene& scene, bool planes, GeometryData& out) {
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const InstanceSpec& spec = scene.instances[i];
    if ((spec.shape == ShapeKind::Plane) != planes) continue;
    out.instances.push_back(device_instance(spec, static_cast<dev::u32>(spec.mesh)));
    out.instance_source.push_back(static_cast<int>(i));
  }
}

}  // namespace

// The triangle table stays on the host: the BVH's leaf packets carry the triangles the device
// tests.
std::size_t GeometryData::device_bytes() const {
  return bytes(instances) + bytes(meshes) + bytes(triangle_normals) + bytes(triangle_materials) +
         bytes(nodes);
}

GeometryData build_geometry(const Scene& scene) {
  GeometryData out;
  append_instances(scene, true, out);
  out.plane_count = static_cast<dev::u32>(out.instances.size());
  append_instances(scene, false, out);
  for (const MeshData& mesh : scene.meshes) append_mesh(mesh, out);
  if (!scene.triangles.empty()) {
    append_loose_triangles(scene.triangles, out);
    out.instances.push_back(loose_triangle_instance(static_cast<dev::u32>(out.meshes.size() - 1)));
    out.instance_source.push_back(-1);
  }
  build_scene_bvh(scene, out);
  return out;
}

}  // namespace clrt
