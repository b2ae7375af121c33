// A wide BVH over a set of boxes, built with the binned surface area heuristic, in host terms;
// bvh_layout.hpp writes it into the device's table.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/bvh_box.hpp"
#include "shared/bvh.h"

namespace clrt {

struct BvhBuildSettings {
  unsigned max_leaf_size = CLRT_BVH_MAX_TRIANGLES;
  // Items the device tests at once (a power of two): a leaf costs as much as its packets of this
  // many items.
  unsigned packet_size = CLRT_BVH_PACKET;
  // SAH cost of visiting one more node, relative to testing one packet.
  // (1, 2 and 3 measured alike within the machine's noise.)
  float node_cost = 1.0f;
};

// One child of a node: an inner node, a leaf of `count` items, or nothing (count 0).
struct BvhLane {
  Box box;
  std::int32_t node = -1;   // >= 0: index of an inner node in BvhTree::nodes
  std::uint32_t first = 0;  // leaf: its items are BvhTree::order[first, first + count)
  std::uint32_t count = 0;
  bool leaf() const { return node < 0 && count > 0; }
};

struct BvhTreeNode {
  BvhLane lane[CLRT_BVH_WIDTH];
};

struct BvhTree {
  std::vector<BvhTreeNode> nodes;    // nodes[0] is the root; a node's children come after it
  std::vector<std::uint32_t> order;  // leaf item i is boxes[order[i]]
  int depth = 0;                     // node levels on the longest root-to-leaf path
};

// Builds a tree of at most CLRT_BVH_MAX_DEPTH node levels; the root is an inner node even for
// zero or one box. Boxes i with alone[i] set are leaves by themselves (empty: none is).
BvhTree build_bvh(const std::vector<Box>& boxes, const BvhBuildSettings& settings,
                  const std::vector<bool>& alone = {});

// The box of everything in the tree.
Box tree_bounds(const BvhTree& tree);

}  // namespace clrt
