#include "device/launch.hpp"

namespace clrt {

compute::event launch(compute::command_queue& queue, compute::kernel& kernel, std::size_t count,
                      std::size_t local_size) {
  if (count == 0) return {};
  const std::size_t global = padded_global_size(count, local_size);
  return queue.enqueue_nd_range_kernel(kernel, 1, nullptr, &global, &local_size);
}

}  // namespace clrt
