#include "geometry/bvh_scene.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>
#include <thread>

#include "geometry/bvh_builder.hpp"
#include "geometry/bvh_layout.hpp"
#include "geometry/instance_bounds.hpp"
#include "shared/ray.h"

namespace clrt {
namespace {

Box triangle_box(const dev::Triangle& t) {
  Box b;
  for (const dev::f4& v : {t.v0, t.v1, t.v2}) b.grow(v.x, v.y, v.z);
  return b;
}

BvhTree build_mesh_bvh(const GeometryData& geometry, const dev::Mesh& mesh) {
  std::vector<Box> boxes(mesh.triangle_count);
  for (dev::u32 i = 0; i < mesh.triangle_count; ++i)
    boxes[i] = triangle_box(geometry.triangles[mesh.first_triangle + i]);
  return build_bvh(boxes, BvhBuildSettings{});
}

// The bottom levels of all meshes, built on every core (large scenes have many meshes).
std::vector<BvhTree> build_mesh_bvhs(const GeometryData& geometry) {
  std::vector<BvhTree> trees(geometry.meshes.size());
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t m = next++; m < trees.size(); m = next++)
      trees[m] = build_mesh_bvh(geometry, geometry.meshes[m]);
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < std::min<std::size_t>(cores, trees.size()); ++t) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  return trees;
}

// Rewrites table[first, first + order.size()) so that entry i is the old entry first + order[i].
template <class T>
void reorder(std::vector<T>& table, std::size_t first, const std::vector<std::uint32_t>& order) {
  std::vector<T> old(table.begin() + first, table.begin() + first + order.size());
  for (std::size_t i = 0; i < order.size(); ++i) table[first + i] = old[order[i]];
}

void reorder_triangles(GeometryData& geometry, const dev::Mesh& mesh, const BvhTree& tree) {
  reorder(geometry.triangles, mesh.first_triangle, tree.order);
  reorder(geometry.triangle_normals, mesh.first_triangle, tree.order);
  reorder(geometry.triangle_materials, mesh.first_triangle, tree.order);
  reorder(geometry.triangle_source, mesh.first_triangle, tree.order);
}

// A mesh instance's world box: its bottom level's root lanes each carried by M, which is
// tighter than the root box carried whole when M rotates.
Box mesh_instance_box(const BvhTree& mesh_tree, const Mat4& m) {
  Box b;
  for (const BvhLane& lane : mesh_tree.nodes[0].lane) b.grow(transformed_box(lane.box, m));
  return b;
}

// The top level's items: the instances after the planes, with their world boxes; spheres the
// device tests in world space may share leaves, everything else is a leaf of its own.
struct TopItems {
  std::vector<Box> boxes;
  std::vector<bool> alone;
  std::vector<std::optional<WorldSphere>> spheres;
};

TopItems top_items(const Scene& scene, const GeometryData& geometry, const std::vector<BvhTree>& mesh_trees) {
  TopItems items;
  for (std::size_t i = geometry.plane_count; i < geometry.instances.size(); ++i) {
    const int source = geometry.instance_source[i];
    const dev::Instance& inst = geometry.instances[i];
    if (inst.shape == CLRT_SHAPE_MESH) {
      const Mat4 m = source < 0 ? Mat4::identity() : scene.instances[source].transform;
      items.boxes.push_back(mesh_instance_box(mesh_trees[inst.mesh], m));
      items.spheres.emplace_back();
    } else {
      items.boxes.push_back(shape_world_box(scene.instances[source]));
      items.spheres.push_back(world_sphere(scene.instances[source]));
    }
    items.alone.push_back(!items.spheres.back());
  }
  return items;
}

bool is_identity(const Mat4& m) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (m.m[r][c] != (r == c ? 1.0 : 0.0)) return false;
  return true;
}

// Per mesh: the instance that is the only one to place it, when it does so with the identity
// transform (the loose triangles' mesh always); else CLRT_NO_HIT.
std::vector<dev::u32> identity_only_instances(const Scene& scene, const GeometryData& geometry) {
  std::vector<dev::u32> only(geometry.meshes.size(), CLRT_NO_HIT);
  std::vector<int> uses(geometry.meshes.size(), 0);
  for (std::size_t i = geometry.plane_count; i < geometry.instances.size(); ++i) {
    const dev::Instance& inst = geometry.instances[i];
    if (inst.shape != CLRT_SHAPE_MESH) continue;
    const int source = geometry.instance_source[i];
    ++uses[inst.mesh];
    if (source < 0 || is_identity(scene.instances[source].transform)) only[inst.mesh] = static_cast<dev::u32>(i);
  }
  for (std::size_t m = 0; m < only.size(); ++m)
    if (uses[m] != 1) only[m] = CLRT_NO_HIT;
  return only;
}

// The top level's items, instances in leaf order; a mesh instance's root block is left to fill
// in once its mesh is laid out (0 meanwhile).
TopLevelItems top_level_items(const GeometryData& geometry, const std::vector<dev::u32>& only,
                              const std::vector<std::optional<WorldSphere>>& spheres) {
  TopLevelItems top;
  top.first_instance = geometry.plane_count;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const auto index = static_cast<dev::u32>(top.first_instance + i);
    const dev::Instance& inst = geometry.instances[index];
    TopLevelItem item;
    item.sphere = spheres[i];
    if (inst.shape == CLRT_SHAPE_MESH) {
      item.mesh_root = 0;
      item.merged = only[inst.mesh] == index;
      for (int r = 0; r < 3; ++r) item.world_to_object[r] = inst.world_to_object[r];
    }
    top.items.push_back(item);
  }
  return top;
}

template <class T>
std::vector<T> in_order(const std::vector<T>& items, const std::vector<std::uint32_t>& order) {
  std::vector<T> out;
  for (std::uint32_t i : order) out.push_back(items[i]);
  return out;
}

}  // namespace

void build_scene_bvh(const Scene& scene, GeometryData& out) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<BvhTree> mesh_trees = build_mesh_bvhs(out);
  for (std::size_t m = 0; m < out.meshes.size(); ++m) reorder_triangles(out, out.meshes[m], mesh_trees[m]);

  const TopItems items = top_items(scene, out, mesh_trees);
  BvhBuildSettings top_settings;
  top_settings.max_leaf_size = CLRT_BVH_MAX_SPHERES;
  const BvhTree top_tree = build_bvh(items.boxes, top_settings, items.alone);
  reorder(out.instances, out.plane_count, top_tree.order);
  reorder(out.instance_source, out.plane_count, top_tree.order);

  const std::vector<dev::u32> only = identity_only_instances(scene, out);
  TopLevelItems top = top_level_items(out, only, in_order(items.spheres, top_tree.order));
  out.nodes.assign(top_level_slots(top_tree, top), dev::BvhNode{});
  for (std::size_t m = 0; m < out.meshes.size(); ++m) {
    dev::Mesh& mesh = out.meshes[m];
    mesh.root_node = append_mesh_level(mesh_trees[m], out.triangles.data() + mesh.first_triangle,
                                       mesh.first_triangle, only[m], out.nodes);
  }
  for (std::size_t i = 0; i < top.items.size(); ++i) {
    const dev::Instance& inst = out.instances[top.first_instance + i];
    if (inst.shape == CLRT_SHAPE_MESH) top.items[i].mesh_root = out.meshes[inst.mesh].root_node;
  }
  write_top_level(top_tree, top, out.nodes);
  out.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace clrt
