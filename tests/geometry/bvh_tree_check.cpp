#include "bvh_tree_check.hpp"

#include <algorithm>

namespace clrt::bvhtest {
namespace {

struct LaneBox {
  float lo[3], hi[3];
};

LaneBox lane_of(const dev::BvhNode& n, int k) {
  const float* lanes[6] = {n.min_x.lane, n.min_y.lane, n.min_z.lane, n.max_x.lane, n.max_y.lane, n.max_z.lane};
  LaneBox b;
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = lanes[a][k];
    b.hi[a] = lanes[3 + a][k];
  }
  return b;
}

bool contains(const LaneBox& outer, const LaneBox& inner) {
  for (int a = 0; a < 3; ++a)
    if (inner.lo[a] < outer.lo[a] || inner.hi[a] > outer.hi[a]) return false;
  return true;
}

bool contains(const LaneBox& box, const Vec3& p) {
  for (int a = 0; a < 3; ++a)
    if (p[a] < box.lo[a] || p[a] > box.hi[a]) return false;
  return true;
}

bool empty(const LaneBox& b) { return b.lo[0] > b.hi[0]; }

class Walker {
 public:
  Walker(const std::vector<dev::BvhNode>& nodes, std::uint32_t first, std::uint32_t count,
         const std::function<std::vector<Vec3>(std::uint32_t)>& points, std::vector<std::string>& errors)
      : nodes_(nodes), first_(first), seen_(count, 0), points_(points), errors_(errors) {}

  void node(std::uint32_t index, int depth) {
    shape_.depth = std::max(shape_.depth, depth);
    if (index >= nodes_.size()) return fail("node index " + std::to_string(index) + " out of range");
    const dev::BvhNode& n = nodes_[index];
    for (int k = 0; k < CLRT_BVH_WIDTH; ++k) {
      const LaneBox box = lane_of(n, k);
      if (n.child[k] >= 0) {
        if (n.count[k] != 0) fail("inner lane with a count");
        const std::uint32_t child = static_cast<std::uint32_t>(n.child[k]);
        if (child <= index) fail("inner lane points backwards (a cycle is possible)");
        else inner(box, child, depth);
      } else if (n.count[k] == 0) {
        if (!empty(box)) fail("empty lane with a non-empty box");
      } else {
        leaf(box, ~static_cast<std::uint32_t>(n.child[k]), n.count[k]);
      }
    }
  }

  TreeShape finish() {
    for (std::size_t i = 0; i < seen_.size(); ++i)
      if (seen_[i] != 1)
        fail("item " + std::to_string(first_ + i) + " is in " + std::to_string(seen_[i]) + " leaves");
    return shape_;
  }

 private:
  void inner(const LaneBox& box, std::uint32_t child, int depth) {
    if (child < nodes_.size())
      for (int k = 0; k < CLRT_BVH_WIDTH; ++k) {
        const LaneBox sub = lane_of(nodes_[child], k);
        if (!empty(sub) && !contains(box, sub)) fail("a child box sticks out of its parent's lane");
      }
    node(child, depth + 1);
  }

  void leaf(const LaneBox& box, std::uint32_t item0, std::uint32_t count) {
    shape_.max_leaf = std::max<int>(shape_.max_leaf, static_cast<int>(count));
    for (std::uint32_t item = item0; item < item0 + count; ++item) {
      if (item < first_ || item - first_ >= seen_.size()) {
        fail("leaf item " + std::to_string(item) + " out of range");
        continue;
      }
      ++seen_[item - first_];
      for (const Vec3& p : points_(item))
        if (!contains(box, p)) fail("item " + std::to_string(item) + " sticks out of its leaf box");
    }
  }

  void fail(const std::string& what) {
    if (errors_.size() < 20) errors_.push_back(what);
  }

  const std::vector<dev::BvhNode>& nodes_;
  std::uint32_t first_;
  std::vector<int> seen_;
  const std::function<std::vector<Vec3>(std::uint32_t)>& points_;
  std::vector<std::string>& errors_;
  TreeShape shape_;
};

}  // namespace

TreeShape check_tree(const std::vector<dev::BvhNode>& nodes, std::uint32_t root,
                     std::uint32_t first, std::uint32_t count,
                     const std::function<std::vector<Vec3>(std::uint32_t)>& points,
                     std::vector<std::string>& errors) {
  Walker walker(nodes, first, count, points, errors);
  walker.node(root, 1);
  return walker.finish();
}

}  // namespace clrt::bvhtest
