// A wide BVH over a set of boxes, built with the binned surface area heuristic.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/bvh_box.hpp"
#include "shared/bvh.h"

namespace clrt {

struct BvhBuildSettings {
  unsigned max_leaf_size = CLRT_BVH_MAX_LEAF;
  // SAH cost of visiting one more node, relative to testing one item.
  float node_cost = 1.0f;
};

struct BvhTree {
  std::vector<dev::BvhNode> nodes;   // nodes[0] is the root; inner lanes index this vector
  std::vector<std::uint32_t> order;  // leaf item first_item + i is boxes[order[i]]
  int depth = 0;                     // node levels on the longest root-to-leaf path
};

// Builds a tree of at most CLRT_BVH_MAX_DEPTH node levels; the root is an inner node even for
// zero or one box. Leaf lanes number their items from `first_item`.
BvhTree build_bvh(const std::vector<Box>& boxes, const BvhBuildSettings& settings,
                  std::uint32_t first_item);

// Appends `tree`'s nodes to `table`, renumbering its inner lanes; returns the root's index.
std::uint32_t append_bvh(const BvhTree& tree, std::vector<dev::BvhNode>& table);
std::uint32_t append_bvh_nodes(const std::vector<dev::BvhNode>& nodes, std::vector<dev::BvhNode>& table);

// The box of lane `k` of `node` (empty for an empty lane).
Box lane_box(const dev::BvhNode& node, int k);

}  // namespace clrt
