#include "tree_cost.hpp"

#include <vector>

#include "geometry/bvh_box.hpp"
#include "geometry/bvh_layout.hpp"

namespace clrt::bench {
namespace {

Box lane_box(const dev::BvhNode& node, int k) {
  Box b;
  b.lo[0] = node.min_x.lane[k], b.hi[0] = node.max_x.lane[k];
  b.lo[1] = node.min_y.lane[k], b.hi[1] = node.max_y.lane[k];
  b.lo[2] = node.min_z.lane[k], b.hi[2] = node.max_z.lane[k];
  return b;
}

// Packets a ray entering the leaf of lane k tests.
double leaf_packets(const dev::BvhNode& node, int k) {
  const dev::u32 count = node.count[k];
  if (count & CLRT_BVH_INSTANCE_LEAF || count & CLRT_BVH_MESH_LEAF) return 1.0;
  if (count & CLRT_BVH_SPHERE_LEAF) return count & ~CLRT_BVH_SPHERE_LEAF;
  return count;
}

}  // namespace

double sah_cost(const BvhTable& table, double node_cost) {
  if (table.empty()) return 0.0;
  const dev::BvhNode root = node_at(table, 0);
  Box root_box;
  for (int k = 0; k < CLRT_BVH_WIDTH; ++k) root_box.grow(lane_box(root, k));
  const double root_area = root_box.half_area();
  if (root_area <= 0.0) return node_cost;
  // Areas in double: a million leaves' terms summed in float would lose the small ones.
  double cost = node_cost;
  std::vector<std::uint32_t> pending{0};
  while (!pending.empty()) {
    const dev::BvhNode node = node_at(table, pending.back());
    pending.pop_back();
    for (int k = 0; k < CLRT_BVH_WIDTH; ++k) {
      if (node.child[k] < 0 && node.count[k] == 0) continue;  // an empty lane
      const double share = lane_box(node, k).half_area() / root_area;
      if (node.child[k] >= 0) {
        cost += share * node_cost;
        pending.push_back(static_cast<std::uint32_t>(node.child[k]));
      } else {
        cost += share * leaf_packets(node, k);
      }
    }
  }
  return cost;
}

}  // namespace clrt::bench
