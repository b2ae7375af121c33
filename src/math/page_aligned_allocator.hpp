// An allocator of whole, page-aligned blocks: an OpenCL CPU device (PoCL) uses memory so aligned
// where it lies (CL_MEM_USE_HOST_PTR) instead of copying it, so a table built on the host in
// such a vector is the device's table too, with no second copy.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>

namespace clrt {

constexpr std::size_t kPageBytes = 4096;

template <class T>
struct PageAlignedAllocator {
  using value_type = T;

  PageAlignedAllocator() = default;
  template <class U>
  PageAlignedAllocator(const PageAlignedAllocator<U>&) noexcept {}  // NOLINT: rebinding

  T* allocate(std::size_t n) {
    const std::size_t bytes = (n * sizeof(T) + kPageBytes - 1) / kPageBytes * kPageBytes;
    void* p = std::aligned_alloc(kPageBytes, bytes == 0 ? kPageBytes : bytes);
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) noexcept { std::free(p); }

  template <class U>
  bool operator==(const PageAlignedAllocator<U>&) const noexcept { return true; }
  template <class U>
  bool operator!=(const PageAlignedAllocator<U>&) const noexcept { return false; }
};

}  // namespace clrt
