// An allocator of whole, page-aligned blocks: an OpenCL CPU device (PoCL) uses memory so aligned
// where it lies (CL_MEM_USE_HOST_PTR) instead of copying it, so a table built on the host in
// such a vector is the device's table too, with no second copy. Blocks of 2 MiB or more come
// from math/fresh_pages.hpp, in huge pages where the kernel has them: the geometry's large
// tables are written once, straight after they are allocated.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>

#include "math/fresh_pages.hpp"

namespace clrt {

constexpr std::size_t kPageBytes = 4096;

template <class T>
struct PageAlignedAllocator {
  using value_type = T;

  PageAlignedAllocator() = default;
  template <class U>
  PageAlignedAllocator(const PageAlignedAllocator<U>&) noexcept {}  // NOLINT: rebinding

  T* allocate(std::size_t n) {
    const std::size_t bytes = block_bytes(n);
    if (bytes >= kHugePageBytes) return static_cast<T*>(map_fresh_pages(bytes));
    void* p = std::aligned_alloc(kPageBytes, bytes);
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = block_bytes(n);
    if (bytes >= kHugePageBytes)
      unmap_fresh_pages(p, bytes);
    else
      std::free(p);
  }

  // Whole pages, at least one; n beyond any possible block is refused as std::vector expects.
  static std::size_t block_bytes(std::size_t n) {
    if (n > (static_cast<std::size_t>(-1) - kPageBytes) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = (n * sizeof(T) + kPageBytes - 1) / kPageBytes * kPageBytes;
    return bytes == 0 ? kPageBytes : bytes;
  }

  template <class U>
  bool operator==(const PageAlignedAllocator<U>&) const noexcept { return true; }
  template <class U>
  bool operator!=(const PageAlignedAllocator<U>&) const noexcept { return false; }
};

}  // namespace clrt
