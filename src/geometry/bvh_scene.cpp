#include "geometry/bvh_scene.hpp"

#include <chrono>
#include <unordered_map>

#include "geometry/bvh_builder.hpp"
#include "geometry/bvh_layout.hpp"
#include "math/parallel_for.hpp"
#include "geometry/bvh_top_items.hpp"

namespace clrt {
namespace {

// The bottom levels of all meshes, built on every core (large scenes have many meshes), then
// each mesh's per-triangle rows written in its leaf order. The rows' tables are made only once
// the trees stand, so that they are not resident beside the builders' scratch (the peak of a
// large mesh's build).
std::vector<BvhTree> build_mesh_bvhs(const std::vector<TriangleSource>& sources, GeometryData& geometry,
                                     const std::function<void(std::size_t)>& rows_written) {
  std::vector<BvhTree> trees(sources.size());
  parallel_for(trees.size(), 1, [&](std::size_t m) {
    trees[m] = build_bvh(triangle_boxes(sources[m]), BvhBuildSettings{});
  });
  std::size_t triangles = 0, normal_rows = 0, material_rows = 0, texcoord_rows = 0;
  for (std::size_t m = 0; m < sources.size(); ++m) {
    triangles += sources[m].size();
    if (sources[m].has_materials()) material_rows += sources[m].size();
    if (sources[m].has_normals()) {
      geometry.meshes[m].normals = static_cast<dev::u32>(normal_rows);
      normal_rows += sources[m].size();
    }
    if (sources[m].has_texcoords()) {
      geometry.meshes[m].texcoords = static_cast<dev::u32>(texcoord_rows);
      texcoord_rows += sources[m].size();
    }
  }
  geometry.triangle_normals.resize(normal_rows);
  geometry.triangle_materials.resize(material_rows);
  geometry.triangle_texcoords.resize(texcoord_rows);
  geometry.triangle_source.resize(triangles);
  parallel_for(trees.size(), 1, [&](std::size_t m) {
    write_triangle_rows(sources[m], trees[m].order, geometry.meshes[m], geometry.mesh_material_rows.at(m),
                        geometry);
    if (rows_written) rows_written(m);
  });
  return trees;
}

// Rewrites table[first, first + order.size()) so that entry i is the old entry first + order[i].
template <class T, class A>
void reorder(std::vector<T, A>& table, std::size_t first, const std::vector<std::uint32_t>& order) {
  std::vector<T> old(table.begin() + first, table.begin() + first + order.size());
  for (std::size_t i = 0; i < order.size(); ++i) table[first + i] = old[order[i]];
}

// The meshes in the order their levels go into the table: that of the top level's only instance
// first when that level stands in for the top level.
std::vector<std::size_t> meshes_in_layout_order(const GeometryData& geometry, bool mesh_only) {
  std::vector<std::size_t> order;
  if (mesh_only) order.push_back(geometry.instances[geometry.plane_count].mesh);
  for (std::size_t m = 0; m < geometry.meshes.size(); ++m)
    if (order.empty() || m != order.front()) order.push_back(m);
  return order;
}

// Instance indices at or after `first`, renumbered for the reorder of the table from `first` on
// by `order` (entry i became the old entry first + order[i]); CLRT_NO_HIT stays.
void follow_reorder(std::vector<dev::u32>& indices, std::size_t first, const std::vector<std::uint32_t>& order) {
  std::unordered_map<dev::u32, dev::u32> moved;
  for (dev::u32 i : indices)
    if (i != CLRT_NO_HIT) moved.emplace(i, CLRT_NO_HIT);
  if (moved.empty()) return;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const auto it = moved.find(static_cast<dev::u32>(first + order[i]));
    if (it != moved.end()) it->second = static_cast<dev::u32>(first + i);
  }
  for (dev::u32& i : indices)
    if (i != CLRT_NO_HIT) i = moved.at(i);
}

// `items` rearranged so that entry i is the old entry order[i]; the old table is freed.
template <class T>
std::vector<T> in_order(std::vector<T> items, const std::vector<std::uint32_t>& order) {
  std::vector<T> out(order.size());
  parallel_for(order.size(), 4096, [&](std::size_t i) { out[i] = items[order[i]]; });
  return out;
}

}  // namespace

void build_scene_bvh(const Scene& scene, const std::vector<TriangleSource>& sources, GeometryData& out,
                     const SceneReleaseHooks& hooks) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<BvhTree> mesh_trees = build_mesh_bvhs(sources, out, hooks.rows_written);

  TopItems items = top_items(scene, out, mesh_trees);
  std::vector<dev::u32> only = identity_only_instances(scene, out);
  if (hooks.instances_read) hooks.instances_read();
  BvhBuildSettings top_settings;
  top_settings.max_leaf_size = CLRT_BVH_MAX_SPHERES;
  const BvhTree top_tree = build_bvh(items.boxes, top_settings, items.alone);
  std::vector<Box>().swap(items.boxes);
  reorder(out.instances, out.plane_count, top_tree.order);
  reorder(out.instance_source, out.plane_count, top_tree.order);
  follow_reorder(only, out.plane_count, top_tree.order);

  const TopLevelItems top = top_level_items(out, std::move(only), in_order(std::move(items.spheres), top_tree.order));
  // A top level of just one mesh that it would lead straight into is that mesh's level, whose
  // root then is the table's: every ray is spared a node (the loose triangles of tetra-6, one
  // model placed as it is).
  const bool mesh_only = top.size() == 1 && top.merged(0);
  out.nodes.assign(mesh_only ? 0 : top_level_slots(top_tree, top), dev::BvhNode{});
  for (std::size_t m : meshes_in_layout_order(out, mesh_only)) {
    dev::Mesh& mesh = out.meshes[m];
    mesh.root_node = append_mesh_level(mesh_trees[m], sources[m], mesh.first_triangle, top.only[m], out.nodes);
  }
  if (!mesh_only) write_top_level(top_tree, top, out.nodes);
  out.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace clrt
