#include "geometry/bvh_builder.hpp"

#include <algorithm>
#include <future>
#include <stdexcept>
#include <utility>

#include "geometry/bvh_split.hpp"

namespace clrt {
namespace {

constexpr int kWidth = CLRT_BVH_WIDTH;

dev::BvhNode empty_node() {
  dev::BvhNode node{};
  for (int k = 0; k < kWidth; ++k) {
    node.min_x.lane[k] = node.min_y.lane[k] = node.min_z.lane[k] = Box::kInf;
    node.max_x.lane[k] = node.max_y.lane[k] = node.max_z.lane[k] = -Box::kInf;
    node.child[k] = CLRT_BVH_EMPTY_LANE;
    node.count[k] = 0;
  }
  return node;
}

void set_lane_box(dev::BvhNode& node, int k, const Box& b) {
  node.min_x.lane[k] = b.lo[0];
  node.min_y.lane[k] = b.lo[1];
  node.min_z.lane[k] = b.lo[2];
  node.max_x.lane[k] = b.hi[0];
  node.max_y.lane[k] = b.hi[1];
  node.max_z.lane[k] = b.hi[2];
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

// Ranges at least this large under the root are built on threads of their own.
constexpr std::uint32_t kParallelItems = 50000;

class Builder {
 public:
  Builder(BuildItems& items, const BvhBuildSettings& settings, std::uint32_t first_item)
      : items_(items), settings_(settings), first_item_(first_item) {}

  void build_root(const Range& all) {
    if (all.size() > capacity(0)) throw std::length_error("BVH: too many items for its depth limit");
    build_node({all, plan(all, 0)}, 0);
  }

  std::vector<dev::BvhNode>& nodes() { return nodes_; }
  int depth() const { return max_depth_ + 1; }

 private:
  // The most items a node at `depth` (the root's is 0, the deepest allowed MAX_DEPTH - 1) can
  // hold when every split below it halves by count.
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
    // On the deepest level allowed, whatever fits in a leaf must become one.
    const bool last_level = depth + 1 >= CLRT_BVH_MAX_DEPTH;
    if (r.size() <= settings_.max_leaf_size && last_level) return p;
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
    // Subtrees work on disjoint slices of the items, so they can be built side by side.
    const bool parallel = depth == 0 && node.range.size() >= kParallelItems;
    std::vector<std::future<Builder>> subtrees(kids.size());
    for (std::size_t k = 0; parallel && k < kids.size(); ++k)
      if (!kids[k].plan.leaf) subtrees[k] = std::async(std::launch::async, [this, &kids, k, depth] {
        Builder sub(items_, settings_, first_item_);
        sub.build_node(kids[k], depth + 1);
        return sub;
      });
    for (std::size_t k = 0; k < kids.size(); ++k) {
      const Child& kid = kids[k];
      set_lane_box(nodes_[index], static_cast<int>(k), kid.range.bounds);
      if (kid.plan.leaf) {
        nodes_[index].child[k] = ~static_cast<dev::i32>(first_item_ + kid.range.begin);
        nodes_[index].count[k] = kid.range.size();
      } else {
        const std::uint32_t child = parallel ? adopt(subtrees[k].get()) : build_node(kid, depth + 1);
        nodes_[index].child[k] = static_cast<dev::i32>(child);
      }
    }
    return index;
  }

  // Appends the nodes of a subtree built apart; returns the index of its root.
  std::uint32_t adopt(Builder&& sub) {
    max_depth_ = std::max(max_depth_, sub.max_depth_);
    return append_bvh_nodes(sub.nodes_, nodes_);
  }

  BuildItems& items_;
  BvhBuildSettings settings_;
  std::uint32_t first_item_;
  std::vector<dev::BvhNode> nodes_;
  int max_depth_ = 0;
};

}  // namespace

BvhTree build_bvh(const std::vector<Box>& boxes, const BvhBuildSettings& settings,
                  std::uint32_t first_item) {
  BuildItems items = make_build_items(boxes);
  const Range all = make_range(items, 0, static_cast<std::uint32_t>(items.size()));
  Builder builder(items, settings, first_item);
  builder.build_root(all);
  BvhTree tree;
  tree.nodes = std::move(builder.nodes());
  tree.depth = builder.depth();
  for (const BuildItem& item : items) tree.order.push_back(item.index);
  return tree;
}

std::uint32_t append_bvh(const BvhTree& tree, std::vector<dev::BvhNode>& table) {
  return append_bvh_nodes(tree.nodes, table);
}

std::uint32_t append_bvh_nodes(const std::vector<dev::BvhNode>& nodes, std::vector<dev::BvhNode>& table) {
  const auto offset = static_cast<dev::i32>(table.size());
  for (dev::BvhNode node : nodes) {
    for (int k = 0; k < kWidth; ++k)
      if (node.child[k] >= 0) node.child[k] += offset;
    table.push_back(node);
  }
  return static_cast<std::uint32_t>(offset);
}

Box lane_box(const dev::BvhNode& node, int k) {
  Box b;
  b.lo[0] = node.min_x.lane[k];
  b.lo[1] = node.min_y.lane[k];
  b.lo[2] = node.min_z.lane[k];
  b.hi[0] = node.max_x.lane[k];
  b.hi[1] = node.max_y.lane[k];
  b.hi[2] = node.max_z.lane[k];
  return b;
}

}  // namespace clrt
