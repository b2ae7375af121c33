// Memory straight from the kernel, in pages of its own, backed by 2 MiB pages where the kernel
// has them (transparent huge pages in `madvise` or `always` mode). Filling a fresh 4 KiB page
// costs a fault and a zeroed page; large tables written once (a file read whole, the geometry's
// tables) spend less than a third of that time in 2 MiB pages (docs/performance.md).
#pragma once

#include <cstddef>

namespace clrt {

// Blocks at least this large are worth their own huge pages.
constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

// `bytes` (> 0) of zeroed memory, page aligned; throws std::bad_alloc when there is none.
void* map_fresh_pages(std::size_t bytes);
// Gives back what map_fresh_pages(bytes) returned.
void unmap_fresh_pages(void* pages, std::size_t bytes) noexcept;

}  // namespace clrt
