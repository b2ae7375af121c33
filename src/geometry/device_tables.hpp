// The host tables that the device reads: page-aligned vectors, so that a CPU device uses them
// where they lie (no second copy of a BVH of 60 MB), while other devices get a copy.
#pragma once

#include <vector>

#include "math/page_aligned_allocator.hpp"
#include "shared/bvh.h"

namespace clrt {

template <class T>
using DeviceTable = std::vector<T, PageAlignedAllocator<T>>;

using BvhTable = DeviceTable<dev::BvhNode>;

}  // namespace clrt
