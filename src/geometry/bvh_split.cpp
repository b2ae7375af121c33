#include "geometry/bvh_split.hpp"

#include <algorithm>
#include <array>

namespace clrt {
namespace {

// Bins per axis: twice as many as the range has items, within these bounds. Most ranges are
// small, and for them setting up and sweeping all 32 bins cost more than binning the items (a
// third of the build time on 100k instances); fewer than 16 made trees that rays traverse 2%
// slower.
constexpr int kMinBins = 16, kMaxBins = 32;

struct Bin {
  std::uint32_t count = 0, alone = 0;
  Box bounds, centroids;
  void add(const Bin& b) {
    count += b.count;
    alone += b.alone;
    bounds.grow(b.bounds);
    centroids.grow(b.centroids);
  }
  void add(const BuildItem& item) {
    ++count;
    alone += item.alone;
    bounds.grow(item.box);
    centroids.grow(item.center[0], item.center[1], item.center[2]);
  }
};

using Bins = std::array<Bin, kMaxBins>;

struct Binning {
  int bins;
  float origin[3], scale[3];  // bin of centre c on axis a: (c - origin[a]) * scale[a]

  Binning(const Box& centroids, std::uint32_t items)
      : bins(static_cast<int>(std::clamp<std::uint32_t>(2 * items, kMinBins, kMaxBins))) {
    for (int a = 0; a < 3; ++a) {
      const float extent = centroids.hi[a] - centroids.lo[a];
      origin[a] = centroids.lo[a];
      scale[a] = extent > 0 ? static_cast<float>(bins) / extent : 0.0f;
    }
  }

  int bin(float center, int axis) const {
    const int b = static_cast<int>((center - origin[axis]) * scale[axis]);
    return std::min(std::max(b, 0), bins - 1);
  }
};

float sah_area(const Box& b) { return b.half_area(); }

struct Candidate {
  int axis = -1, last_left_bin = 0;
  float weighted = 0;  // area(left) * leaf_cost(left) + area(right) * leaf_cost(right)
  Bin left, right;     // what the two sides hold
};

// Sweeps the first `count` bins of one axis from both ends and keeps the cheapest boundary in
// `best`.
void sweep(const Bins& bins, int count, int axis, const SahCosts& costs, Candidate& best) {
  Bins right;
  Bin acc;
  for (int b = count - 1; b > 0; --b) {
    acc.add(bins[b]);
    right[b] = acc;
  }
  Bin left;
  for (int b = 0; b + 1 < count; ++b) {
    left.add(bins[b]);
    const Bin& r = right[b + 1];
    if (left.count == 0 || r.count == 0) continue;
    const float weighted = sah_area(left.bounds) * costs.leaf_cost(left.count, left.alone) +
                           sah_area(r.bounds) * costs.leaf_cost(r.count, r.alone);
    if (best.axis < 0 || weighted < best.weighted) best = {axis, b, weighted, left, r};
  }
}

}  // namespace

BuildItems make_build_items(const std::vector<Box>& boxes, const std::vector<bool>& alone) {
  BuildItems items(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    items[i].box = boxes[i];
    items[i].index = static_cast<std::uint32_t>(i);
    items[i].alone = !alone.empty() && alone[i];
    // An empty box (a mesh without triangles) has no centre; any finite stand-in will do.
    for (int a = 0; a < 3; ++a) items[i].center[a] = boxes[i].empty() ? 0.0f : boxes[i].center(a);
  }
  return items;
}

Range make_range(const BuildItems& items, std::uint32_t begin, std::uint32_t end) {
  Range r;
  r.begin = begin;
  r.end = end;
  for (std::uint32_t i = begin; i < end; ++i) {
    r.bounds.grow(items[i].box);
    r.centroids.grow(items[i].center[0], items[i].center[1], items[i].center[2]);
    r.alone += items[i].alone;
  }
  return r;
}

std::optional<Split> split_sah(BuildItems& items, const Range& range, const SahCosts& costs) {
  const Binning binning(range.centroids, range.size());
  std::array<Bins, 3> bins;
  for (std::uint32_t i = range.begin; i < range.end; ++i)
    for (int a = 0; a < 3; ++a) bins[a][binning.bin(items[i].center[a], a)].add(items[i]);
  Candidate best;
  for (int a = 0; a < 3; ++a)
    if (binning.scale[a] > 0) sweep(bins[a], binning.bins, a, costs, best);
  if (best.axis < 0) return std::nullopt;

  const auto middle = std::partition(items.begin() + range.begin, items.begin() + range.end,
                                     [&](const BuildItem& item) {
                                       return binning.bin(item.center[best.axis], best.axis) <= best.last_left_bin;
                                     });
  const auto mid = static_cast<std::uint32_t>(middle - items.begin());
  const float area = sah_area(range.bounds);
  Split split;
  // The sides are the bins' unions: no pass over the items to measure them again.
  split.left = {range.begin, mid, best.left.bounds, best.left.centroids, best.left.alone};
  split.right = {mid, range.end, best.right.bounds, best.right.centroids, best.right.alone};
  split.cost = costs.node_cost + (area > 0 ? best.weighted / area : costs.leaf_cost(range.size(), range.alone));
  return split;
}

Split split_median(BuildItems& items, const Range& range) {
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (range.centroids.hi[a] - range.centroids.lo[a] >
        range.centroids.hi[axis] - range.centroids.lo[axis])
      axis = a;
  const std::uint32_t mid = range.begin + range.size() / 2;
  std::nth_element(items.begin() + range.begin, items.begin() + mid, items.begin() + range.end,
                   [&](const BuildItem& a, const BuildItem& b) { return a.center[axis] < b.center[axis]; });
  Split split;
  split.left = make_range(items, range.begin, mid);
  split.right = make_range(items, mid, range.end);
  split.cost = 0;
  return split;
}

}  // namespace clrt
