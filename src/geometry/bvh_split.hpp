// Splitting a range of build items in two: by the binned surface area heuristic, or at the
// median when the tree must stay shallow.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/bvh_box.hpp"

namespace clrt {

struct BuildItems {
  explicit BuildItems(const std::vector<Box>& item_boxes);

  const std::vector<Box>& boxes;
  std::vector<float> centers;        // 3 per item: its box's centre
  std::vector<std::uint32_t> order;  // items in tree order; ranges are slices of it

  float center(std::uint32_t item, int axis) const { return centers[3 * item + axis]; }
};

struct Range {
  std::uint32_t begin = 0, end = 0;  // into BuildItems::order
  Box bounds;                        // of the items' boxes
  Box centroids;                     // of the items' centres
  std::uint32_t size() const { return end - begin; }
};

Range make_range(const BuildItems& items, std::uint32_t begin, std::uint32_t end);

struct Split {
  Range left, right;
  float cost = 0;  // SAH cost of the two halves relative to testing the range's items as a leaf
};

// The cheapest split of `range` at a bin boundary of its centroid box, with order[begin, end)
// partitioned accordingly; nothing (and order untouched) when every centre coincides.
std::optional<Split> split_sah(BuildItems& items, const Range& range, float node_cost);

// Halves `range` by count along the axis where the centres spread most.
Split split_median(BuildItems& items, const Range& range);

}  // namespace clrt
