// Partitioning a range of the BVH build's items in place, on every core for a large range, into
// exactly the order std::partition gives: the tree (and so the order of triangles in the leaves)
// is the same whether a build runs on one core or many.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "math/parallel_for.hpp"

namespace clrt {

// Ranges at least this large are partitioned in blocks of this many items on every core.
constexpr std::size_t kParallelBlock = 16384;

// What a partition may gather about the items as it tests them: `add(item, left)` for each item
// (possibly more than once for one item), and `merge` of what two parts of the range gathered.
struct SeenNothing {
  template <class Item>
  void add(const Item&, bool) {}
  void merge(const SeenNothing&) {}
};

// Moves the items of [first, last) for which `left(item)` holds before the others, as
// std::partition does (libstdc++'s bidirectional algorithm, which it uses for random-access
// iterators too): its scans from both ends swap the k-th item from the front that belongs on the
// right with the k-th item from the back that belongs on the left. The same swaps are made here
// by blocks: one pass tests every item, a second makes each block's swaps. `seen` gathers what
// the tests saw. Returns the first item of the right side.
template <class Item, class Left, class Seen>
Item* partition_like_std(Item* first, Item* last, const Left& left, Seen& seen) {
  const auto n = static_cast<std::size_t>(last - first);
  if (n < 2 * kParallelBlock)
    return std::partition(first, last, [&](const Item& item) {
      const bool l = left(item);
      seen.add(item, l);
      return l;
    });
  const std::size_t blocks = (n + kParallelBlock - 1) / kParallelBlock;
  const auto block_begin = [](std::size_t b) { return b * kParallelBlock; };
  const auto block_end = [n](std::size_t b) { return std::min(n, (b + 1) * kParallelBlock); };
  std::vector<std::uint8_t> goes_left(n);
  std::vector<std::size_t> lefts(blocks, 0);
  std::vector<Seen> seen_in(blocks);
  parallel_for(blocks, 1, [&](std::size_t b) {
    // Gathered apart from the shared vectors: neighbouring blocks' entries share cache lines.
    std::size_t count = 0;
    Seen block_seen;
    for (std::size_t i = block_begin(b); i < block_end(b); ++i) {
      const bool l = left(first[i]);
      goes_left[i] = l ? 1 : 0;
      count += l;
      block_seen.add(first[i], l);
    }
    lefts[b] = count;
    seen_in[b] = block_seen;
  });
  for (const Seen& s : seen_in) seen.merge(s);
  std::size_t middle = 0;
  for (std::size_t c : lefts) middle += c;

  // Per block, the items that must move: those in front of `middle` that go right and those
  // behind it that go left. Only the block that holds `middle` is counted item by item.
  std::vector<std::size_t> front_moves(blocks, 0), back_moves(blocks, 0);
  for (std::size_t b = 0; b < blocks; ++b) {
    if (block_end(b) <= middle) {
      front_moves[b] = (block_end(b) - block_begin(b)) - lefts[b];
    } else if (block_begin(b) >= middle) {
      back_moves[b] = lefts[b];
    } else {
      for (std::size_t i = block_begin(b); i < middle; ++i) front_moves[b] += !goes_left[i];
      const std::size_t lefts_in_front = (middle - block_begin(b)) - front_moves[b];
      back_moves[b] = lefts[b] - lefts_in_front;
    }
  }
  // front_rank[b]: the movers from the front before block b; back_rank[b]: those from the back
  // after it (the last item that goes left has rank 0).
  std::vector<std::size_t> front_rank(blocks, 0), back_rank(blocks, 0);
  for (std::size_t b = 1; b < blocks; ++b) front_rank[b] = front_rank[b - 1] + front_moves[b - 1];
  for (std::size_t b = blocks - 1; b-- > 0;) back_rank[b] = back_rank[b + 1] + back_moves[b + 1];

  // The position behind `middle` of the item before `j` that goes left.
  const auto previous_left = [&](std::size_t j) {
    do --j;
    while (!goes_left[j]);
    return j;
  };
  parallel_for(blocks, 1, [&](std::size_t b) {
    std::size_t moves = front_moves[b];
    if (moves == 0) return;
    // The partner of this block's first mover: the item of rank front_rank[b] from the back.
    const std::size_t rank = front_rank[b];
    std::size_t c = blocks - 1;
    while (rank >= back_rank[c] + back_moves[c]) --c;
    std::size_t j = previous_left(block_end(c));
    for (std::size_t skip = rank - back_rank[c]; skip > 0; --skip) j = previous_left(j);
    for (std::size_t i = block_begin(b);; ++i) {
      if (goes_left[i]) continue;
      std::swap(first[i], first[j]);
      if (--moves == 0) break;
      j = previous_left(j);
    }
  });
  return first + middle;
}

template <class Item, class Left>
Item* partition_like_std(Item* first, Item* last, const Left& left) {
  SeenNothing nothing;
  return partition_like_std(first, last, left, nothing);
}

}  // namespace clrt
