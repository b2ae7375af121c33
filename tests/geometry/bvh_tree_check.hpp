// Structural checks of a BVH in the device node table, walked on the host.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "math/vec3.hpp"
#include "shared/bvh.h"

namespace clrt::bvhtest {

struct TreeShape {
  int depth = 0;      // node levels on the longest path
  int max_leaf = 0;   // most items in one leaf
};

// Walks the tree at `root`, whose leaves must hold every item of [first, first + count) exactly
// once. `points(item)` lists points the item's box must contain. Every inner lane's box must
// contain all of its child's lane boxes. Problems are appended to `errors`.
TreeShape check_tree(const std::vector<dev::BvhNode>& nodes, std::uint32_t root,
                     std::uint32_t first, std::uint32_t count,
                     const std::function<std::vector<Vec3>(std::uint32_t)>& points,
                     std::vector<std::string>& errors);

}  // namespace clrt::bvhtest
