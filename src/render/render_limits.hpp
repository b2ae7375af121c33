// Everything a render will need, checked against what clrt allows and what the machine has,
// before any work (BVH build, kernel build, render). See docs/reliability.md.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "device/device_select.hpp"
#include "render/render_options.hpp"
#include "scene/scene.hpp"

namespace clrt {

// A render that cannot go ahead. exit_code() is 2 when the request itself is beyond clrt's limits
// (scene or command line) and 1 when this machine lacks the memory for it.
class RenderLimitError : public std::runtime_error {
 public:
  RenderLimitError(int exit_code, const std::string& message)
      : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

struct DeviceBudget {
  std::string name;
  std::uint64_t wavefront = 0;       // the rays per queue it will render with
  std::uint64_t lanes = 1;           // waves in flight, each with its own queues
  std::uint64_t max_allocation = 0;  // CL_DEVICE_MAX_MEM_ALLOC_SIZE
  std::uint64_t global_memory = 0;   // CL_DEVICE_GLOBAL_MEM_SIZE
  bool uses_host_memory = false;     // CL_DEVICE_HOST_UNIFIED_MEMORY: its buffers are host memory
};

struct MachineBudget {
  std::uint64_t host_available = 0;  // bytes of memory this process can still take (memory_limit)
  std::vector<DeviceBudget> devices;
};

// What the machine and `devices` offer a render with `options` (whose wavefront 0 means each
// device's default).
MachineBudget measure_budget(const std::vector<DeviceEntry>& devices, const RenderOptions& options);

// Throws RenderLimitError naming the real cause: an image beyond limits::kMaxImageSide or
// limits::kMaxPixels, samples, depth or shadow samples beyond their limits (whichever loader made
// `scene`), a queue buffer larger than a device's largest allocation, or a render whose estimated
// device or host memory exceeds what there is.
void check_render_limits(const Scene& scene, const RenderOptions& options,
                         const MachineBudget& budget);

}  // namespace clrt
