// The device tables' allocator: whole pages, small blocks from the heap and large ones mapped
// afresh (math/fresh_pages.hpp); every block page aligned, so that a CPU device can use it in
// place, and freed by the path that made it.
#include <catch2/catch.hpp>

#include <cstdint>
#include <fstream>
#include <new>
#include <string>
#include <vector>

#include "math/page_aligned_allocator.hpp"

using clrt::PageAlignedAllocator;

namespace {

bool page_aligned(const void* p) { return reinterpret_cast<std::uintptr_t>(p) % clrt::kPageBytes == 0; }

// Whether `p` lies in a mapping of its own that starts at `p` (/proc/self/maps): what a block of
// fresh pages is, and what a block from the heap is not.
bool starts_a_mapping(const void* p) {
  std::ifstream maps("/proc/self/maps");
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  std::string line;
  while (std::getline(maps, line))
    if (std::stoull(line.substr(0, line.find('-')), nullptr, 16) == at) return true;
  return false;
}

}  // namespace

TEST_CASE("blocks of every size are page aligned and hold what is written", "[math][memory]") {
  for (std::size_t count : {std::size_t{1}, std::size_t{1000}, std::size_t{1} << 19, std::size_t{3} << 20}) {
    std::vector<std::uint32_t, PageAlignedAllocator<std::uint32_t>> table(count);
    CHECK(page_aligned(table.data()));
    bool zero = true, same = true;
    for (std::size_t i = 0; i < count; ++i) zero = zero && table[i] == 0;  // value-initialised
    for (std::size_t i = 0; i < count; ++i) table[i] = static_cast<std::uint32_t>(i * 2654435761u);
    for (std::size_t i = 0; i < count; ++i) same = same && table[i] == static_cast<std::uint32_t>(i * 2654435761u);
    CHECK(zero);
    CHECK(same);
  }
}

TEST_CASE("blocks of 2 MiB or more are fresh pages of their own, smaller ones are not", "[math][memory]") {
  PageAlignedAllocator<char> allocator;
  char* large = allocator.allocate(clrt::kHugePageBytes);
  CHECK(starts_a_mapping(large));
  allocator.deallocate(large, clrt::kHugePageBytes);
  CHECK_FALSE(starts_a_mapping(large));  // given back to the kernel, not kept by the heap
  char* small = allocator.allocate(clrt::kHugePageBytes - clrt::kPageBytes);
  CHECK(page_aligned(small));
  allocator.deallocate(small, clrt::kHugePageBytes - clrt::kPageBytes);
}

TEST_CASE("a count beyond any block is refused, not wrapped round", "[math][memory]") {
  PageAlignedAllocator<std::uint64_t> allocator;
  CHECK_THROWS_AS(allocator.allocate(static_cast<std::size_t>(-1) / 4), std::bad_array_new_length);
}
