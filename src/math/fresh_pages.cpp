#include "math/fresh_pages.hpp"

#include <sys/mman.h>

#include <new>

namespace clrt {

void* map_fresh_pages(std::size_t bytes) {
  void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  // Advice only: where the kernel has no huge pages the block is ordinary memory.
  ::madvise(p, bytes, MADV_HUGEPAGE);
  return p;
}

void unmap_fresh_pages(void* pages, std::size_t bytes) noexcept { ::munmap(pages, bytes); }

}  // namespace clrt
