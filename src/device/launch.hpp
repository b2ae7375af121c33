// Every kernel is launched through here: an explicit local size (PoCL builds a work-group
// function per kernel and local size, and a NULL local size is erratic), and a global size
// padded to it; kernels guard `if (i >= count) return;`.
#pragma once

#include <cstddef>

#include "device/opencl.hpp"

namespace clrt {

inline std::size_t padded_global_size(std::size_t count, std::size_t local_size) {
  return (count + local_size - 1) / local_size * local_size;
}

// Enqueues `kernel` over `count` work-items; a zero count enqueues nothing and returns an
// empty event.
compute::event launch(compute::command_queue& queue, compute::kernel& kernel, std::size_t count,
                      std::size_t local_size);

}  // namespace clrt
