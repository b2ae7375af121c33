#include "geometry/geometry_data.hpp"

#include <cstdint>
#include <deque>
#include <functional>
#include <stdexcept>

#include "geometry/bvh_scene.hpp"
#include "geometry/emitter_table.hpp"
#include "geometry/instance_motion.hpp"
#include "geometry/instance_table.hpp"
#include "geometry/mesh_table.hpp"

namespace clrt {
namespace {

template <class T>
std::size_t bytes(const DeviceTable<T>& table) {
  return sizeof(T) * table.size();
}

void append_instances(const Scene& scene, bool planes, GeometryData& out) {
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const InstanceSpec& spec = scene.instances[i];
    if ((spec.shape == ShapeKind::Plane) != planes) continue;
    const dev::u32 rows = spec.shape == ShapeKind::Mesh ? out.mesh_material_rows.at(static_cast<std::size_t>(spec.mesh))
                                                        : CLRT_NO_MATERIAL_ROWS;
    dev::Instance inst = device_instance(spec, static_cast<dev::u32>(spec.mesh), rows);
    if (spec.motion >= 0) {
      inst.motion = static_cast<dev::u32>(out.motions.size());
      out.motions.push_back(
          device_motion(spec.transform, scene.end_transforms[static_cast<std::size_t>(spec.motion)]));
    }
    out.instances.push_back(inst);
    out.instance_source.push_back(static_cast<int>(i));
  }
}

// Where each source's rows of triangle materials start, for those that have them.
std::vector<dev::u32> material_rows(const std::vector<TriangleSource>& sources) {
  std::vector<dev::u32> rows;
  std::size_t next = 0;
  for (const TriangleSource& source : sources) {
    rows.push_back(source.has_materials() ? static_cast<dev::u32>(next) : CLRT_NO_MATERIAL_ROWS);
    if (source.has_materials()) next += source.size();
  }
  return rows;
}

GeometryData build_tables(const Scene& scene, const SceneReleaseHooks& hooks) {
  GeometryData out;
  std::vector<TriangleSource> sources(scene.meshes.begin(), scene.meshes.end());
  if (!scene.triangles.empty()) sources.emplace_back(scene.triangles);
  out.mesh_material_rows = material_rows(sources);
  // Sized once: grown by doubling, a table of 3M instances (384 MB) was twice that for a moment.
  const std::size_t instances = scene.instances.size() + (scene.triangles.empty() ? 0 : 1);
  out.instances.reserve(instances);
  out.instance_source.reserve(instances);
  append_instances(scene, true, out);
  out.plane_count = static_cast<dev::u32>(out.instances.size());
  append_instances(scene, false, out);
  if (!scene.triangles.empty()) {
    out.instances.push_back(
        loose_triangle_instance(static_cast<dev::u32>(sources.size() - 1), out.mesh_material_rows.back()));
    out.instance_source.push_back(-1);
  }
  std::size_t triangles = 0;
  for (const TriangleSource& source : sources) {
    out.meshes.push_back(device_mesh(source, static_cast<dev::u32>(triangles)));
    triangles += source.size();
    if (triangles > UINT32_MAX) throw std::length_error("the scene has more than 2^32 - 1 triangles");
  }
  build_emitter_table(scene, sources, out);
  build_scene_bvh(scene, sources, out, hooks);
  return out;
}

}  // namespace

std::size_t GeometryData::triangle_count() const {
  std::size_t count = 0;
  for (const dev::Mesh& mesh : meshes) count += mesh.triangle_count;
  return count;
}

std::size_t GeometryData::device_bytes() const {
  return bytes(instances) + bytes(motions) + bytes(meshes) + bytes(triangle_normals) + bytes(triangle_materials) + bytes(triangle_texcoords) +
         bytes(nodes);
}

GeometryData build_geometry(const Scene& scene) { return build_tables(scene, {}); }

GeometryData build_geometry_for_render(Scene& scene) {
  SceneReleaseHooks hooks;
  hooks.rows_written = [&scene](std::size_t m) {
    if (m >= scene.meshes.size()) return;  // the loose triangles' mesh
    MeshData& mesh = scene.meshes[m];
    std::vector<Vec3>().swap(mesh.normals);
    std::vector<std::uint32_t>().swap(mesh.corner_normals);
    std::vector<std::array<float, 2>>().swap(mesh.texcoords);
    std::vector<std::uint32_t>().swap(mesh.corner_texcoords);
  };
  hooks.instances_read = [&scene] { std::deque<InstanceSpec>().swap(scene.instances); };
  GeometryData out = build_tables(scene, hooks);
  release_mesh_data(scene);
  std::vector<int>().swap(out.instance_source);
  std::vector<dev::u32>().swap(out.triangle_source);
  return out;
}

void release_mesh_data(Scene& scene) {
  for (MeshData& mesh : scene.meshes) {
    MeshData released;
    released.path = std::move(mesh.path);
    mesh = std::move(released);
  }
}

}  // namespace clrt
