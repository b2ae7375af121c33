// Every launch of an integrator goes through its Launcher: the lane's command queue, the
// work-group size, and, when --stats asks for times, each launch's event kept under its kernel's
// name and pass for the Profiler to read later (nothing here waits on the device).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "device/device_context.hpp"
#include "device/typed_kernel.hpp"

namespace clrt {

struct TimedLaunch {
  const char* kernel;
  std::uint32_t pass;
  compute::event event;
};

class Launcher {
 public:
  Launcher(DeviceContext& device, std::size_t local_size, bool timed)
      : device_(device), local_size_(local_size), timed_(timed) {}

  template <class Args>
  void launch(TypedKernel<Args>& kernel, const Args& args, std::size_t items, std::uint32_t pass) {
    compute::event e = kernel.launch(device_.queue(), args, items, local_size_);
    if (timed_ && items > 0) launches_.push_back({Args::kName, pass, std::move(e)});
  }

  DeviceContext& device() { return device_; }

  // The launches kept so far: a mark to forget those after it (a wave that is retried), and
  // all of them handed over.
  std::size_t mark() const { return launches_.size(); }
  void forget_since(std::size_t mark) {
    launches_.erase(launches_.begin() + static_cast<std::ptrdiff_t>(mark), launches_.end());
  }
  std::vector<TimedLaunch> take() {
    std::vector<TimedLaunch> out;
    out.swap(launches_);
    return out;
  }

 private:
  DeviceContext& device_;
  std::size_t local_size_;
  bool timed_;
  std::vector<TimedLaunch> launches_;
};

}  // namespace clrt
