#include "geometry/bvh_scene.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include "geometry/bvh_builder.hpp"
#include "geometry/instance_bounds.hpp"

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
  return build_bvh(boxes, BvhBuildSettings{}, mesh.first_triangle);
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
  for (int k = 0; k < CLRT_BVH_WIDTH; ++k) b.grow(transformed_box(lane_box(mesh_tree.nodes[0], k), m));
  return b;
}

std::vector<Box> instance_boxes(const Scene& scene, const GeometryData& geometry,
                                const std::vector<BvhTree>& mesh_trees) {
  std::vector<Box> boxes;
  for (std::size_t i = geometry.plane_count; i < geometry.instances.size(); ++i) {
    const int source = geometry.instance_source[i];
    const Mat4 m = source < 0 ? Mat4::identity() : scene.instances[source].transform;
    const dev::Instance& inst = geometry.instances[i];
    boxes.push_back(inst.shape == CLRT_SHAPE_MESH
                        ? mesh_instance_box(mesh_trees[inst.mesh], m)
                        : shape_world_box(scene.instances[source]));
  }
  return boxes;
}

}  // namespace

void build_scene_bvh(const Scene& scene, GeometryData& out) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<BvhTree> mesh_trees = build_mesh_bvhs(out);
  for (std::size_t m = 0; m < out.meshes.size(); ++m) reorder_triangles(out, out.meshes[m], mesh_trees[m]);

  BvhBuildSettings top;
  top.max_leaf_size = 1;  // a leaf's instance may be a mesh, whose traversal the stack nests
  BvhTree top_tree = build_bvh(instance_boxes(scene, out, mesh_trees), top, out.plane_count);
  reorder(out.instances, out.plane_count, top_tree.order);
  reorder(out.instance_source, out.plane_count, top_tree.order);

  out.nodes = std::move(top_tree.nodes);
  for (std::size_t m = 0; m < out.meshes.size(); ++m)
    out.meshes[m].root_node = append_bvh(mesh_trees[m], out.nodes);
  out.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace clrt
