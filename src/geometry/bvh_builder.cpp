#include "geometry/bvh_builder.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "geometry/bvh_split.hpp"

namespace clrt {
namespace {

constexpr int kWidth = CLRT_BVH_WIDTH;

float& lane(dev::f4& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : k == 2 ? v.z : v.w; }
float lane(const dev::f4& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : k == 2 ? v.z : v.w; }

dev::BvhNode empty_node() {
  dev::BvhNode node{};
  for (int k = 0; k < kWidth; ++k) {
    lane(node.min_x, k) = lane(node.min_y, k) = lane(node.min_z, k) = Box::kInf;
    lane(node.max_x, k) = lane(node.max_y, k) = lane(node.max_z, k) = -Box::kInf;
    node.child[k] = CLRT_BVH_EMPTY_LANE;
    node.count[k] = 0;
  }
  return node;
}

void set_lane_box(dev::BvhNode& node, int k, const Box& b) {
  lane(node.min_x, k) = b.lo[0];
  lane(node.min_y, k) = b.lo[1];
  lane(node.min_z, k) = b.lo[2];
  lane(node.max_x, k) = b.hi[0];
  lane(node.max_y, k) = b.hi[1];
  lane(node.max_z, k) = b.hi[2];
}

// How a range is stored: as one leaf, or as the two halves of `split`. A forced plan halves by
// count because the range would not otherwise fit in the depth that remains.
struct Plan {
  bool leaf = true;
  bool forced = false;
  Split split;
};

struct Child {
  Range range;
  Plan plan;
};

class Builder {
 public:
  Builder(const std::vector<Box>& boxes, const BvhBuildSettings& settings, std::uint32_t first_item)
      : items_(boxes), settings_(settings), first_item_(first_item) {}

  BvhTree run() {
    BvhTree tree;
    const Range all = make_range(items_, 0, static_cast<std::uint32_t>(items_.boxes.size()));
    tree.bounds = all.bounds;
    if (all.size() > capacity(0)) throw std::length_error("BVH: too many items for its depth limit");
    build_node({all, plan(all, 0)}, 0);
    tree.nodes = std::move(nodes_);
    tree.order = std::move(items_.order);
    tree.depth = max_depth_ + 1;
    return tree;
  }

 private:
  // The most items a node at `depth` can hold when every split below it halves by count.
  double capacity(int depth) const {
    double items = settings_.max_leaf_size;
    for (int d = depth; d < CLRT_BVH_MAX_DEPTH; ++d) items *= kWidth;
    return items;
  }

  bool must_force(const Range& r, int depth) const { return r.size() > capacity(depth + 1); }

  // The plan for `r` as (part of) a node at `depth`.
  Plan plan(const Range& r, int depth) {
    Plan p;
    if (r.size() <= 1) return p;
    p.forced = must_force(r, depth);
    if (p.forced && r.size() > settings_.max_leaf_size) {
      p.leaf = false;
      p.split = split_median(items_, r);
      return p;
    }
    std::optional<Split> sah = split_sah(items_, r, settings_.node_cost);
    if (r.size() <= settings_.max_leaf_size && (!sah || sah->cost >= r.size())) return p;
    p.leaf = false;
    p.split = sah ? *sah : split_median(items_, r);
    return p;
  }

  // The splittable child to split next: the largest by count while depth is tight, else the
  // largest by area (the one rays are most likely to enter); -1 when none is.
  static int next_to_split(const std::vector<Child>& kids) {
    const bool tight = std::any_of(kids.begin(), kids.end(), [](const Child& c) {
      return !c.plan.leaf && c.plan.forced;
    });
    const auto key = [tight](const Child& c) {
      return tight ? static_cast<float>(c.range.size()) : c.range.bounds.half_area();
    };
    int best = -1;
    for (int k = 0; k < static_cast<int>(kids.size()); ++k)
      if (!kids[k].plan.leaf && (best < 0 || key(kids[k]) > key(kids[best]))) best = k;
    return best;
  }

  std::vector<Child> open_node(const Child& node, int depth) {
    std::vector<Child> kids{node};
    while (static_cast<int>(kids.size()) < kWidth) {
      const int k = next_to_split(kids);
      if (k < 0) break;
      const Split split = kids[k].plan.split;
      kids[k] = {split.left, plan(split.left, depth)};
      kids.push_back({split.right, plan(split.right, depth)});
    }
    return kids;
  }

  // `node.plan` was made for the level above, where a node one level deeper could be forced
  // differently; it is kept unless that changed.
  std::uint32_t build_node(const Child& node, int depth) {
    max_depth_ = std::max(max_depth_, depth);
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(empty_node());
    if (node.range.size() == 0) return index;
    const bool keep = node.plan.forced == must_force(node.range, depth);
    const std::vector<Child> kids = open_node(keep ? node : Child{node.range, plan(node.range, depth)}, depth);
    for (int k = 0; k < static_cast<int>(kids.size()); ++k) {
      const Child& kid = kids[k];
      set_lane_box(nodes_[index], k, kid.range.bounds);
      if (kid.plan.leaf) {
        nodes_[index].child[k] = ~static_cast<dev::i32>(first_item_ + kid.range.begin);
        nodes_[index].count[k] = kid.range.size();
      } else {
        const std::uint32_t child = build_node(kid, depth + 1);
        nodes_[index].child[k] = static_cast<dev::i32>(child);
      }
    }
    return index;
  }

  BuildItems items_;
  BvhBuildSettings settings_;
  std::uint32_t first_item_;
  std::vector<dev::BvhNode> nodes_;
  int max_depth_ = 0;
};

}  // namespace

BvhTree build_bvh(const std::vector<Box>& boxes, const BvhBuildSettings& settings,
                  std::uint32_t first_item) {
  return Builder(boxes, settings, first_item).run();
}

std::uint32_t append_bvh(const BvhTree& tree, std::vector<dev::BvhNode>& table) {
  const auto offset = static_cast<dev::i32>(table.size());
  for (dev::BvhNode node : tree.nodes) {
    for (int k = 0; k < kWidth; ++k)
      if (node.child[k] >= 0) node.child[k] += offset;
    table.push_back(node);
  }
  return static_cast<std::uint32_t>(offset);
}

Box lane_box(const dev::BvhNode& node, int k) {
  Box b;
  b.lo[0] = lane(node.min_x, k);
  b.lo[1] = lane(node.min_y, k);
  b.lo[2] = lane(node.min_z, k);
  b.hi[0] = lane(node.max_x, k);
  b.hi[1] = lane(node.max_y, k);
  b.hi[2] = lane(node.max_z, k);
  return b;
}

}  // namespace clrt
