#include "geometry/bvh_split.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include "geometry/bvh_partition.hpp"
#include "math/parallel_for.hpp"

namespace clrt {
namespace {

// Bins per axis: twice as many as the range has items, within these bounds. Most ranges are
// small, and for them setting up and sweeping all 32 bins cost more than binning the items (a
// third of the build time on 100k instances); fewer than 16 made trees that rays traverse 2%
// slower.
constexpr int kMinBins = 16, kMaxBins = 32;

// Ranges this small are binned item by item into the bins they occupy: cheaper than setting up
// and sweeping 16 bins per axis, for the same split.
constexpr std::uint32_t kSparseItems = 16;

// Four floats handled at once (GCC and Clang vector extensions): x, y, z and a lane kept 0.
typedef float V4 __attribute__((vector_size(16)));
typedef std::int32_t I4 __attribute__((vector_size(16)));

constexpr float kInf = Box::kInf;
constexpr float kMaxFloat = std::numeric_limits<float>::max();

// x, y, z from p[0..2]; p[3] is read but not used (BuildItem's index or flag lies there).
V4 load_xyz(const float* p) {
  V4 v;
  std::memcpy(&v, p, sizeof v);
  const I4 xyz{-1, -1, -1, 0};
  return reinterpret_cast<V4>(reinterpret_cast<I4>(v) & xyz);
}

// Lane by lane, exactly std::min(a, b) and std::max(a, b) (what Box::grow does).
V4 min4(V4 a, V4 b) { return b < a ? b : a; }
V4 max4(V4 a, V4 b) { return a < b ? b : a; }

Box to_box(V4 lo, V4 hi) {
  Box b;
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = lo[a];
    b.hi[a] = hi[a];
  }
  return b;
}

// Half the surface area of the box [lo, hi], as Box::half_area computes it.
float half_area(V4 lo, V4 hi) {
  if (lo[0] > hi[0]) return 0.0f;
  const V4 d = hi - lo;
  return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

float finite_or_limit(float v) { return v > -kMaxFloat ? (v < kMaxFloat ? v : kMaxFloat) : -kMaxFloat; }

[[gnu::noinline]] V4 centers_beyond_range(const BuildItem& item) {
  return V4{item.center(0), item.center(1), item.center(2), 0.0f};
}

// An item's centre on every axis (BuildItem::center).
inline V4 centers(const BuildItem& item) {
  const V4 c = (load_xyz(item.lo) + load_xyz(item.hi)) * 0.5f;
  const V4 zero{0, 0, 0, 0};
  const I4 finite = (c - c) == zero;
  return finite[0] && finite[1] && finite[2] ? c : centers_beyond_range(item);
}

// The box of some items' centres.
struct CentreBox {
  V4 lo{kInf, kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf, -kInf};

  void grow(V4 c) {
    lo = min4(lo, c);
    hi = max4(hi, c);
  }
  void grow(const CentreBox& b) {
    lo = min4(lo, b.lo);
    hi = max4(hi, b.hi);
  }
  Box box() const { return to_box(lo, hi); }
};

// Left uninitialised by default: a range sets up only the bins it uses (most ranges are small,
// and setting up all 96 cost more than binning their items). Binning is bound by its stores
// (three axes' bins updated per item), so the bins keep no box of their items' centres: the
// partition that follows a split gathers those of its two sides.
struct Bin {
  V4 lo, hi;  // of the items' boxes
  std::uint32_t count, alone;

  static Bin empty() {
    const V4 inf{kInf, kInf, kInf, kInf};
    return {inf, -inf, 0, 0};
  }

  void add(const Bin& b) {
    lo = min4(lo, b.lo);
    hi = max4(hi, b.hi);
    count += b.count;
    alone += b.alone;
  }

  void add(const BuildItem& item) {
    lo = min4(lo, load_xyz(item.lo));
    hi = max4(hi, load_xyz(item.hi));
    ++count;
    alone += item.alone;
  }
};

// One range's bins on every axis; only the first `bins` of each are set up.
struct BinGrid {
  std::array<std::array<Bin, kMaxBins>, 3> axis;

  explicit BinGrid(int bins) {
    for (auto& bins_of_axis : axis) std::fill_n(bins_of_axis.begin(), bins, Bin::empty());
  }

  void add(const BinGrid& g, int bins) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < bins; ++b) axis[a][b].add(g.axis[a][b]);
  }
};

// Where a centre falls: bin floor((c * pre - origin) * scale), clamped to the bins in single
// precision before it becomes an integer, so that no value (not even a NaN) is converted out of
// range. `pre` is 1, or 1/2 on an axis whose centres span more than the largest float: the span
// of the halves is finite.
struct Binning {
  int bins;
  V4 pre{1, 1, 1, 1}, origin{0, 0, 0, 0}, scale{0, 0, 0, 0};

  Binning(const Box& centroids, std::uint32_t items)
      : bins(static_cast<int>(std::clamp<std::uint32_t>(2 * items, kMinBins, kMaxBins))) {
    for (int a = 0; a < 3; ++a) {
      float lo = centroids.lo[a], extent = centroids.hi[a] - lo;
      if (std::isinf(extent)) {
        pre[a] = 0.5f;
        lo *= 0.5f;
        extent = centroids.hi[a] * 0.5f - lo;
      }
      origin[a] = lo;
      scale[a] = extent > 0 ? static_cast<float>(bins) / extent : 0.0f;
    }
  }

  bool spread(int axis) const { return scale[axis] > 0; }

  I4 bins_of(V4 center) const {
    V4 t = (center * pre - origin) * scale;
    const V4 zero{0, 0, 0, 0};
    const V4 last = zero + static_cast<float>(bins - 1);
    t = t > zero ? t : zero;
    t = t < last ? t : last;
    return __builtin_convertvector(t, I4);
  }

  int bin(float center, int axis) const {
    float t = (center * pre[axis] - origin[axis]) * scale[axis];
    const auto last = static_cast<float>(bins - 1);
    t = t > 0 ? t : 0.0f;
    t = t < last ? t : last;
    return static_cast<int>(t);
  }
};

void bin_items(const BuildItem* items, std::size_t count, const Binning& binning, BinGrid& grid) {
  for (std::size_t i = 0; i < count; ++i) {
    const I4 b = binning.bins_of(centers(items[i]));
    for (int a = 0; a < 3; ++a) grid.axis[a][b[a]].add(items[i]);
  }
}

// Fills `grid` with the bins of `range`, counted on every core when it is large and
// `on_every_core`: minima, maxima and counts do not depend on the order they are gathered in.
void bin_range(const BuildItems& items, const Range& range, const Binning& binning, bool on_every_core,
               BinGrid& grid) {
  const BuildItem* first = items.data() + range.begin;
  if (!on_every_core || range.size() < 2 * kParallelBlock) {
    bin_items(first, range.size(), binning, grid);
    return;
  }
  const std::size_t blocks = (range.size() + kParallelBlock - 1) / kParallelBlock;
  std::vector<BinGrid> parts(blocks, BinGrid(binning.bins));
  parallel_for(blocks, 1, [&](std::size_t b) {
    const std::size_t begin = b * kParallelBlock;
    bin_items(first + begin, std::min<std::size_t>(kParallelBlock, range.size() - begin), binning, parts[b]);
  });
  for (const BinGrid& part : parts) grid.add(part, binning.bins);
}

// The bins of one axis that hold items, in bin order: boundaries between empty bins split the
// items no differently from the boundary before them, so only these are swept.
struct Occupied {
  int count = 0;
  std::array<int, kMaxBins> bin;
  std::array<const Bin*, kMaxBins> contents;

  void push(int b, const Bin* c) {
    bin[count] = b;
    contents[count++] = c;
  }
};

// (Filled in place: an Occupied is 400 bytes, and copying three of them a split was a tenth of
// the time of the small ranges' splits.)
void occupied(const std::array<Bin, kMaxBins>& bins, int count, Occupied& o) {
  for (int b = 0; b < count; ++b)
    if (bins[b].count > 0) o.push(b, &bins[b]);
}

// A small range's items with their centres and bins on every axis, worked out once.
struct SmallRange {
  std::uint32_t size;
  std::array<V4, kSparseItems> center;
  std::array<I4, kSparseItems> bin;

  SmallRange(const BuildItems& items, const Range& range, const Binning& binning) : size(range.size()) {
    for (std::uint32_t i = 0; i < size; ++i) {
      center[i] = centers(items[range.begin + i]);
      bin[i] = binning.bins_of(center[i]);
    }
  }
};

// The occupied bins of one axis of a small range, held in `store`.
void occupied_sparse(const BuildItems& items, const Range& range, const SmallRange& small, int axis,
                     std::array<Bin, kSparseItems>& store, Occupied& o) {
  // Keys of bin and item, sorted by insertion (a handful of them).
  std::array<std::uint32_t, kSparseItems> key;
  for (std::uint32_t i = 0; i < small.size; ++i) {
    const std::uint32_t k = static_cast<std::uint32_t>(small.bin[i][axis]) << 8 | i;
    std::uint32_t j = i;
    for (; j > 0 && key[j - 1] > k; --j) key[j] = key[j - 1];
    key[j] = k;
  }
  for (std::uint32_t i = 0; i < small.size; ++i) {
    const int b = static_cast<int>(key[i] >> 8);
    if (o.count == 0 || o.bin[o.count - 1] != b) {
      store[o.count] = Bin::empty();
      o.push(b, &store[o.count]);
    }
    const std::uint32_t item = key[i] & 0xff;
    store[o.count - 1].add(items[range.begin + item]);
  }
}

// std::partition of a small range by the bins already worked out: libstdc++'s algorithm (see
// partition_like_std), step for step, so the order is the same.
std::uint32_t partition_small(BuildItems& items, const Range& range, const SmallRange& small, int axis,
                              int last_left_bin, CentreBox sides[2]) {
  bool left[kSparseItems];
  for (std::uint32_t i = 0; i < small.size; ++i) {
    left[i] = small.bin[i][axis] <= last_left_bin;
    sides[left[i] ? 0 : 1].grow(small.center[i]);
  }
  std::uint32_t first = 0, last = small.size;
  while (true) {
    for (;; ++first)
      if (first == last) return range.begin + first;
      else if (!left[first]) break;
    --last;
    for (;; --last)
      if (first == last) return range.begin + first;
      else if (left[last]) break;
    std::swap(items[range.begin + first], items[range.begin + last]);
    ++first;
  }
}

struct Candidate {
  int axis = -1, last_left_bin = 0;
  float weighted = 0;  // area(left) * leaf_cost(left) + area(right) * leaf_cost(right)
};

// Sweeps one axis's occupied bins from both ends and keeps the cheapest boundary in `best`; of
// equal costs the first (by axis, then bin) is kept.
void sweep(const Occupied& bins, int axis, const SahCosts& costs, Candidate& best) {
  float right_area[kMaxBins];
  std::uint32_t right_count[kMaxBins], right_alone[kMaxBins];
  V4 lo = bins.contents[bins.count - 1]->lo, hi = bins.contents[bins.count - 1]->hi;
  std::uint32_t count = 0, alone = 0;
  for (int g = bins.count - 1; g > 0; --g) {
    const Bin& b = *bins.contents[g];
    lo = min4(lo, b.lo);
    hi = max4(hi, b.hi);
    right_area[g] = half_area(lo, hi);
    right_count[g] = count += b.count;
    right_alone[g] = alone += b.alone;
  }
  lo = bins.contents[0]->lo;
  hi = bins.contents[0]->hi;
  count = alone = 0;
  for (int g = 0; g + 1 < bins.count; ++g) {
    const Bin& b = *bins.contents[g];
    lo = min4(lo, b.lo);
    hi = max4(hi, b.hi);
    count += b.count;
    alone += b.alone;
    const float weighted = half_area(lo, hi) * costs.leaf_cost(count, alone) +
                           right_area[g + 1] * costs.leaf_cost(right_count[g + 1], right_alone[g + 1]);
    if (best.axis < 0 || weighted < best.weighted) best = {axis, bins.bin[g], weighted};
  }
}

// The items of the occupied bins on one side of the split, whose centres `centres` bounds.
Range side(std::uint32_t begin, std::uint32_t end, const Occupied& bins, bool left, int last_left_bin,
           const CentreBox& centres) {
  Bin all = Bin::empty();
  for (int g = 0; g < bins.count; ++g)
    if ((bins.bin[g] <= last_left_bin) == left) all.add(*bins.contents[g]);
  return {begin, end, to_box(all.lo, all.hi), centres.box(), all.alone};
}

// A split's test of an item (bvh_partition.hpp), gathering the boxes of the centres of the items
// it sends left and right (apart, not indexed by side: kept in registers).
struct SplitTest {
  const Binning* binning;
  int axis, last_left_bin;
  CentreBox left, right;

  bool operator()(const BuildItem& item) {
    const V4 c = centers(item);
    const bool goes_left = binning->bin(c[axis], axis) <= last_left_bin;
    if (goes_left)
      left.grow(c);
    else
      right.grow(c);
    return goes_left;
  }
  SplitTest part() const { return {binning, axis, last_left_bin, {}, {}}; }
  void merge(const SplitTest& s) {
    left.grow(s.left);
    right.grow(s.right);
  }
};

}  // namespace

Box BuildItem::box() const {
  Box b;
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = lo[a];
    b.hi[a] = hi[a];
  }
  return b;
}

float BuildItem::center(int axis) const {
  const float c = 0.5f * (lo[axis] + hi[axis]);
  if (std::isfinite(c)) return c;
  return 0.5f * finite_or_limit(lo[axis]) + 0.5f * finite_or_limit(hi[axis]);
}

BuildItems make_build_items(const std::vector<Box>& boxes, const std::vector<bool>& alone) {
  BuildItems items(boxes.size());
  parallel_for(boxes.size(), kParallelBlock, [&](std::size_t i) {
    BuildItem& item = items[i];
    for (int a = 0; a < 3; ++a) {
      item.lo[a] = boxes[i].lo[a];
      item.hi[a] = boxes[i].hi[a];
    }
    item.index = static_cast<std::uint32_t>(i);
    item.alone = !alone.empty() && alone[i] ? 1 : 0;
  });
  return items;
}

Range make_range(const BuildItems& items, std::uint32_t begin, std::uint32_t end) {
  Range r;
  r.begin = begin;
  r.end = end;
  for (std::uint32_t i = begin; i < end; ++i) {
    r.bounds.grow(items[i].box());
    r.centroids.grow(items[i].center(0), items[i].center(1), items[i].center(2));
    r.alone += items[i].alone;
  }
  return r;
}

std::optional<Split> split_sah(BuildItems& items, const Range& range, const SahCosts& costs, bool on_every_core) {
  const Binning binning(range.centroids, range.size());
  std::optional<SmallRange> small;
  std::array<std::array<Bin, kSparseItems>, 3> small_bins;
  BinGrid grid(range.size() <= kSparseItems ? 0 : binning.bins);
  if (range.size() <= kSparseItems)
    small.emplace(items, range, binning);
  else
    bin_range(items, range, binning, on_every_core, grid);
  std::array<Occupied, 3> bins;
  Candidate best;
  for (int a = 0; a < 3; ++a) {
    if (!binning.spread(a)) continue;
    if (small)
      occupied_sparse(items, range, *small, a, small_bins[a], bins[a]);
    else
      occupied(grid.axis[a], binning.bins, bins[a]);
    sweep(bins[a], a, costs, best);
  }
  if (best.axis < 0) return std::nullopt;

  std::uint32_t mid = 0;
  CentreBox centres[2];  // of the left and the right side
  if (small) {
    mid = partition_small(items, range, *small, best.axis, best.last_left_bin, centres);
  } else {
    BuildItem* const first = items.data() + range.begin;
    BuildItem* const last = items.data() + range.end;
    // Each item's centre joins its side's box as the partition tests it.
    SplitTest test = SplitTest{&binning, best.axis, best.last_left_bin, {}, {}};
    BuildItem* const middle =
        on_every_core ? partition_like_std(first, last, test) : partition_testing(first, last, test);
    mid = range.begin + static_cast<std::uint32_t>(middle - first);
    centres[0] = test.left;
    centres[1] = test.right;
  }
  Split split;
  // The sides' boxes are the bins' unions: no pass over the items to measure them again.
  split.left = side(range.begin, mid, bins[best.axis], true, best.last_left_bin, centres[0]);
  split.right = side(mid, range.end, bins[best.axis], false, best.last_left_bin, centres[1]);
  const float area = range.bounds.half_area();
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
                   [&](const BuildItem& a, const BuildItem& b) { return a.center(axis) < b.center(axis); });
  Split split;
  split.left = make_range(items, range.begin, mid);
  split.right = make_range(items, mid, range.end);
  split.cost = 0;
  return split;
}

}  // namespace clrt
