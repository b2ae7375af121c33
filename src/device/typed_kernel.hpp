// A kernel of a built program with its argument structure: the only way the renderer launches.
#pragma once

#include "device/kernel_args.hpp"
#include "device/launch.hpp"

namespace clrt {

template <class Args>
class TypedKernel {
 public:
  explicit TypedKernel(const compute::program& program) : kernel_(program, Args::kName) {}

  // Binds `args` and enqueues `items` work-items in groups of `local_size`; nothing for zero items.
  compute::event launch(compute::command_queue& queue, const Args& args, std::size_t items,
                        std::size_t local_size) {
    if (items == 0) return {};
    bind_args(kernel_, args);
    return clrt::launch(queue, kernel_, items, local_size);
  }

  const compute::kernel& kernel() const { return kernel_; }

 private:
  compute::kernel kernel_;
};

}  // namespace clrt
