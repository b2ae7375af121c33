// Splitting a range of build items in two: by the binned surface area heuristic, or at the
// median when the tree must stay shallow.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/bvh_box.hpp"
#include "math/page_aligned_allocator.hpp"

namespace clrt {

// What the build moves around: each item's box travels with it, so that the passes over a range
// read memory in order. 32 bytes: the index and the flag fill the lanes after each corner, so
// that a corner is one 16-byte load and the partitions move little.
struct BuildItem {
  float lo[3];
  std::uint32_t index;  // of the box the build was given
  float hi[3];
  std::uint32_t alone;  // 1: may only be a leaf by itself

  Box box() const;
  // The box's centre on `axis`; finite for any box: a bound beyond the float range (a sphere
  // scaled by 1e126) or not a number counts as the largest float, and an empty box's centre is 0.
  float center(int axis) const;
};

// The items in tree order: ranges are slices of it, partitioned in place. (32 MB for a million
// triangles, written once where they are allocated: in huge pages where the kernel has them.)
using BuildItems = std::vector<BuildItem, PageAlignedAllocator<BuildItem>>;

// `alone[i]` says whether boxes[i] must be alone in its leaf (empty: none must).
BuildItems make_build_items(const std::vector<Box>& boxes, const std::vector<bool>& alone);

struct Range {
  std::uint32_t begin = 0, end = 0;  // into BuildItems
  Box bounds;                        // of the items' boxes
  Box centroids;                     // of the items' centres
  std::uint32_t alone = 0;           // items that must be alone in their leaf
  std::uint32_t size() const { return end - begin; }
};

Range make_range(const BuildItems& items, std::uint32_t begin, std::uint32_t end);

struct Split {
  Range left, right;
  float cost = 0;  // SAH cost of the two halves, comparable with SahCosts::leaf_cost
};

// The SAH's costs, relative to testing one packet of items.
struct SahCosts {
  float node_cost = 1;       // of visiting one more node
  unsigned packet_shift = 0;  // items tested at once: 1 << packet_shift
  // Of leaves holding `items`, `alone` of which are each a leaf by themselves. (A shift, not a
  // division: the SAH sweeps evaluate this hundreds of times per split.)
  float leaf_cost(std::uint32_t items, std::uint32_t alone = 0) const {
    const std::uint32_t grouped = items - alone;
    return static_cast<float>(((grouped + (1u << packet_shift) - 1) >> packet_shift) + alone);
  }
};

// The cheapest split of `range` at a bin boundary of its centroid box, with items[begin, end)
// partitioned accordingly; nothing (and the items untouched) when every centre coincides. With
// `on_every_core`, a large range is binned and partitioned on every core (for the splits above
// the subtrees that are built side by side; below them that would only add threads that wait for
// a core). The split is the same either way.
std::optional<Split> split_sah(BuildItems& items, const Range& range, const SahCosts& costs, bool on_every_core);

// Halves `range` by count along the axis where the centres spread most.
Split split_median(BuildItems& items, const Range& range);

}  // namespace clrt
