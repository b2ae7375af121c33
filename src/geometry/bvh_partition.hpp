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

// Moves the items of [first, last) for which `left(item)` holds before the others, as
// std::partition does (libstdc++'s bidirectional algorithm, which it uses for random-access
// iterators too): its scans from both ends swap the k-th item from the front that belongs on the
// right with the k-th item from the back that belongs on the left. The same swaps are made here
// by blocks. Returns the first item of the right side.
template <class Item, class Left>
Item* partition_like_std(Item* first, Item* last, const Left& left) {
  const auto n = static_cast<std::size_t>(last - first);
  if (n < 2 * kParallelBlock) return std::partition(first, last, left);
  const std::size_t blocks = (n + kParallelBlock - 1) / kParallelBlock;
  const auto block_end = [&](std::size_t b) { return std::min(n, (b + 1) * kParallelBlock); };
  std::vector<std::uint8_t> goes_left(n);
  std::vector<std::size_t> lefts(blocks, 0);
  parallel_for(blocks, 1, [&](std::size_t b) {
    for (std::size_t i = b * kParallelBlock; i < block_end(b); ++i) lefts[b] += goes_left[i] = left(first[i]) ? 1 : 0;
  });
  std::size_t middle = 0;
  for (std::size_t c : lefts) middle += c;

  // The items that must move: those in front of `middle` that go right, ranked from the front,
  // and those behind it that go left, ranked from the back.
  const auto leaves_front = [&](std::size_t i) { return i < middle && !goes_left[i]; };
  const auto leaves_back = [&](std::size_t i) { return i >= middle && goes_left[i]; };
  std::vector<std::size_t> front_rank(blocks + 1, 0), back_rank(blocks + 1, 0);
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t i = b * kParallelBlock; i < block_end(b); ++i) {
      front_rank[b + 1] += leaves_front(i);
      back_rank[b] += leaves_back(i);
    }
  for (std::size_t b = 0; b < blocks; ++b) front_rank[b + 1] += front_rank[b];  // of block b's first
  for (std::size_t b = blocks; b-- > 0;) back_rank[b] += back_rank[b + 1];     // one past block b's first
  const std::size_t swaps = front_rank[blocks];
  std::vector<std::size_t> front_out(swaps), back_out(swaps);
  parallel_for(blocks, 1, [&](std::size_t b) {
    std::size_t f = front_rank[b], k = back_rank[b];
    for (std::size_t i = b * kParallelBlock; i < block_end(b); ++i) {
      if (leaves_front(i)) front_out[f++] = i;
      if (leaves_back(i)) back_out[--k] = i;
    }
  });
  parallel_for(swaps, kParallelBlock, [&](std::size_t s) { std::swap(first[front_out[s]], first[back_out[s]]); });
  return first + middle;
}

}  // namespace clrt
