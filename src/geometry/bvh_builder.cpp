#include "geometry/bvh_builder.hpp"

#include <algorithm>
#include <array>
#include <future>
#include <stdexcept>
#include <utility>

#include "geometry/bvh_split.hpp"
#include "math/parallel_for.hpp"

namespace clrt {
namespace {

constexpr int kWidth = CLRT_BVH_WIDTH;

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
  // `sure_leaf_size` items fit in any leaf: the depth limit's capacity counts with it.
  Builder(BuildItems& items, const BvhBuildSettings& settings, unsigned sure_leaf_size)
      : items_(items), settings_(settings), sure_leaf_size_(sure_leaf_size) {
    if (settings.packet_size == 0 || (settings.packet_size & (settings.packet_size - 1)) != 0)
      throw std::invalid_argument("BVH: the packet size must be a power of two");
    while ((1u << packet_shift_) < settings.packet_size) ++packet_shift_;
  }

  void build_root(const Range& all) {
    if (all.size() > capacity(0)) throw std::length_error("BVH: too many items for its depth limit");
    build_node({all, plan(all, 0)}, 0);
  }

  std::vector<BvhTreeNode>& nodes() { return nodes_; }
  int depth() const { return max_depth_ + 1; }

 private:
  // The most items a node at `depth` (the root's is 0, the deepest allowed MAX_DEPTH - 1) can
  // hold when every split below it halves by count.
  double capacity(int depth) const {
    double items = sure_leaf_size_;
    for (int d = depth; d < CLRT_BVH_MAX_DEPTH; ++d) items *= kWidth;
    return items;
  }

  bool must_force(const Range& r, int depth) const { return r.size() > capacity(depth + 1); }

  // The plan for `r` as (part of) a node at `depth`.
  Plan plan(const Range& r, int depth) {
    Plan p;
    if (r.size() <= 1) return p;
    p.forced = must_force(r, depth);
    if (p.forced && r.size() > sure_leaf_size_) {
      p.leaf = false;
      p.split = split_median(items_, r);
      return p;
    }
    const SahCosts costs{settings_.node_cost, packet_shift_};
    // The root's node is planned before its subtrees are built side by side: its splits alone
    // are worth spreading over the cores.
    const std::optional<Split> sah = split_sah(items_, r, costs, depth == 0 && parallel_threads() > 1);
    // On the deepest level allowed, whatever fits in a leaf must become one.
    const bool last_level = depth + 1 >= CLRT_BVH_MAX_DEPTH;
    const bool may_be_leaf = r.size() <= settings_.max_leaf_size && r.alone == 0;
    p.leaf = may_be_leaf && (last_level || !sah || sah->cost >= costs.leaf_cost(r.size()));
    if (!p.leaf) p.split = sah ? *sah : split_median(items_, r);
    return p;
  }

  // A node's children while it is opened: up to kWidth, held in place (a node is opened for
  // every eight or so items of the tree, too often for a heap allocation each).
  struct Children {
    std::array<Child, kWidth> kid;
    int count = 0;
  };

  // The child to split next: while depth is tight, the largest by count of those that must
  // split; else the largest by area (the one rays are most likely to enter) of those the SAH
  // splits. A child planned as a leaf stays one even when lanes are free: splitting it further
  // (Embree's way) made smaller leaves that cost more to visit than the packets saved (9%
  // fewer rays per second over the SPD scenes, 40% on shells-5). -1 when none is.
  static int next_to_split(const Children& kids) {
    const auto end = kids.kid.begin() + kids.count;
    const bool tight = std::any_of(kids.kid.begin(), end, [](const Child& c) {
      return !c.plan.leaf && c.plan.forced;
    });
    const auto key = [tight](const Child& c) {
      return tight ? static_cast<float>(c.range.size()) : c.range.bounds.half_area();
    };
    int best = -1;
    for (int k = 0; k < kids.count; ++k)
      if (!kids.kid[k].plan.leaf && (best < 0 || key(kids.kid[k]) > key(kids.kid[best]))) best = k;
    return best;
  }

  void open_node(const Child& node, int depth, Children& kids) {
    kids.kid[0] = node;
    kids.count = 1;
    while (kids.count < kWidth) {
      const int k = next_to_split(kids);
      if (k < 0) break;
      const Split split = kids.kid[k].plan.split;
      kids.kid[k] = {split.left, plan(split.left, depth)};
      kids.kid[kids.count++] = {split.right, plan(split.right, depth)};
    }
  }

  // `node.plan` was made for the level above, where a node one level deeper could be forced
  // differently; it is kept unless that changed.
  std::uint32_t build_node(const Child& node, int depth) {
    max_depth_ = std::max(max_depth_, depth);
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    if (node.range.size() == 0) return index;
    const bool keep = node.plan.forced == must_force(node.range, depth);
    Children kids;
    open_node(keep ? node : Child{node.range, plan(node.range, depth)}, depth, kids);
    // Subtrees work on disjoint slices of the items, so they can be built side by side.
    const bool parallel = depth == 0 && node.range.size() >= kParallelItems && parallel_threads() > 1;
    std::array<std::future<Builder>, kWidth> subtrees;
    for (int k = 0; parallel && k < kids.count; ++k)
      if (!kids.kid[k].plan.leaf) subtrees[k] = std::async(std::launch::async, [this, &kids, k, depth] {
        Builder sub(items_, settings_, sure_leaf_size_);
        sub.build_node(kids.kid[k], depth + 1);
        return sub;
      });
    for (int k = 0; k < kids.count; ++k) {
      const Child& kid = kids.kid[k];
      BvhLane lane;
      lane.box = kid.range.bounds;
      if (kid.plan.leaf) {
        lane.first = kid.range.begin;
        lane.count = kid.range.size();
      } else {
        lane.node = static_cast<std::int32_t>(parallel ? adopt(subtrees[k].get()) : build_node(kid, depth + 1));
      }
      nodes_[index].lane[k] = lane;
    }
    return index;
  }

  // Appends the nodes of a subtree built apart; returns the index of its root.
  std::uint32_t adopt(Builder&& sub) {
    max_depth_ = std::max(max_depth_, sub.max_depth_);
    const auto offset = static_cast<std::int32_t>(nodes_.size());
    for (BvhTreeNode node : sub.nodes_) {
      for (BvhLane& lane : node.lane)
        if (lane.node >= 0) lane.node += offset;
      nodes_.push_back(node);
    }
    return static_cast<std::uint32_t>(offset);
  }

  BuildItems& items_;
  BvhBuildSettings settings_;
  unsigned sure_leaf_size_;
  unsigned packet_shift_ = 0;
  std::vector<BvhTreeNode> nodes_;
  int max_depth_ = 0;
};

}  // namespace

BvhTree build_bvh(const std::vector<Box>& boxes, const BvhBuildSettings& settings,
                  const std::vector<bool>& alone) {
  BuildItems items = make_build_items(boxes, alone);
  const Range all = make_range(items, 0, static_cast<std::uint32_t>(items.size()));
  Builder builder(items, settings, all.alone == 0 ? settings.max_leaf_size : 1);
  builder.build_root(all);
  BvhTree tree;
  tree.nodes = std::move(builder.nodes());
  tree.depth = builder.depth();
  for (const BuildItem& item : items) tree.order.push_back(item.index);
  return tree;
}

Box tree_bounds(const BvhTree& tree) {
  Box b;
  for (const BvhLane& lane : tree.nodes.at(0).lane) b.grow(lane.box);
  return b;
}

}  // namespace clrt
