#include "geometry/bvh_top_items.hpp"

#include "math/parallel_for.hpp"
#include "shared/ray.h"

namespace clrt {
namespace {

// What a mesh instance's world box is made of: the lane boxes two levels under its bottom
// level's root, each carried by M, which is tighter than the root box carried whole when M
// rotates (5% more rays per second through 10-10k rotated instances).
BoxSet mesh_box_set(const BvhTree& mesh_tree) {
  std::vector<Box> boxes;
  for (const BvhLane& lane : mesh_tree.nodes[0].lane) {
    if (lane.node < 0) boxes.push_back(lane.box);
    else
      for (const BvhLane& sub : mesh_tree.nodes[static_cast<std::size_t>(lane.node)].lane) boxes.push_back(sub.box);
  }
  return BoxSet(boxes);
}

bool is_identity(const Mat4& m) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (m.m[r][c] != (r == c ? 1.0 : 0.0)) return false;
  return true;
}

}  // namespace

TopItems top_items(const Scene& scene, const GeometryData& geometry, const std::vector<BvhTree>& mesh_trees) {
  std::vector<BoxSet> mesh_boxes;
  for (const BvhTree& tree : mesh_trees) mesh_boxes.push_back(mesh_box_set(tree));
  const std::size_t count = geometry.instances.size() - geometry.plane_count;
  TopItems items;
  items.boxes.resize(count);
  items.spheres.resize(count);
  parallel_for(count, 1024, [&](std::size_t item) {
    const std::size_t i = geometry.plane_count + item;
    const int source = geometry.instance_source[i];
    const dev::Instance& inst = geometry.instances[i];
    if (source >= 0 && scene.instances[source].motion >= 0) {
      const InstanceSpec& spec = scene.instances[source];
      const Mat4& end = scene.end_transforms[static_cast<std::size_t>(spec.motion)];
      items.boxes[item] = inst.shape == CLRT_SHAPE_MESH
                              ? moving_box(mesh_boxes[inst.mesh], spec.transform, end)
                              : moving_shape_box(spec, end);
    } else if (inst.shape == CLRT_SHAPE_MESH) {
      const Mat4 m = source < 0 ? Mat4::identity() : scene.instances[source].transform;
      items.boxes[item] = transformed_box(mesh_boxes[inst.mesh], m);
    } else {
      items.boxes[item] = shape_world_box(scene.instances[source]);
      items.spheres[item] = SphereLane::of(world_sphere(scene.instances[source]));
    }
  });
  items.alone.reserve(count);
  for (const SphereLane& sphere : items.spheres) items.alone.push_back(!sphere);
  return items;
}

std::vector<dev::u32> identity_only_instances(const Scene& scene, const GeometryData& geometry) {
  std::vector<dev::u32> only(geometry.meshes.size(), CLRT_NO_HIT);
  std::vector<int> uses(geometry.meshes.size(), 0);
  for (std::size_t i = geometry.plane_count; i < geometry.instances.size(); ++i) {
    const dev::Instance& inst = geometry.instances[i];
    if (inst.shape != CLRT_SHAPE_MESH) continue;
    const int source = geometry.instance_source[i];
    ++uses[inst.mesh];
    if (source < 0 || (scene.instances[source].motion < 0 && is_identity(scene.instances[source].transform)))
      only[inst.mesh] = static_cast<dev::u32>(i);
  }
  for (std::size_t m = 0; m < only.size(); ++m)
    if (uses[m] != 1) only[m] = CLRT_NO_HIT;
  return only;
}

TopLevelItems top_level_items(const GeometryData& geometry, std::vector<dev::u32> only,
                              std::vector<SphereLane> spheres) {
  TopLevelItems top;
  top.first_instance = geometry.plane_count;
  top.instances = geometry.instances.data();
  top.meshes = geometry.meshes.data();
  top.only = std::move(only);
  top.spheres = std::move(spheres);
  return top;
}

}  // namespace clrt
