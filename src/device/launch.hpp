// Every kernel is launched through here: one explicit local size for all kernels (PoCL builds a
// work-group function per kernel and local size, and a NULL local size is erratic), and a
// global size padded to it; kernels guard `if (i >= count) return;`.
#pragma once

#include <cstddef>

#include "device/opencl.hpp"

namespace clrt {

constexpr std::size_t kLocalSize = 64;

inline std::size_t padded_global_size(std::size_t count) {
  return (count + kLocalSize - 1) / kLocalSize * kLocalSize;
}

// Enqueues `kernel` over `count` work-items; a zero count enqueues nothing and returns an
// empty event.
compute::event launch(compute::command_queue& queue, compute::kernel& kernel, std::size_t count);

}  // namespace clrt
