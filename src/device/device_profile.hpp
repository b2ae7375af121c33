// What clrt builds and launches with on a device, from one table keyed by what the device is:
// its class, its platform and whether it rounds division and sqrt correctly. Every entry is
// either a launch parameter or part of one fixed program-option string, so that a device's
// program text and options never depend on the scene and the kernel caches stay warm across
// scenes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "device/opencl.hpp"

namespace clrt {

enum class DeviceClass { Cpu, Gpu, Other };

// What the profile table's rows are matched against.
struct DeviceKey {
  DeviceClass device_class = DeviceClass::Cpu;
  std::string platform;                // as CL_PLATFORM_NAME gives it
  bool rounds_divide_sqrt = false;     // CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT
};

struct DeviceProfile {
  DeviceClass device_class = DeviceClass::Cpu;
  std::size_t local_size = 0;            // work-items per work-group, every kernel
  std::uint32_t wavefront = 0;           // rays per queue when the user names none
  // Waves in flight on the device, each on its own command queue with its own queues: while
  // one waits for the host, the other's kernels run.
  std::uint32_t lanes = 0;
  // The options every program on the device is built with (DeviceContext::build); a program
  // adds its own after them.
  std::string program_options;
};

DeviceClass classify(const compute::device& device);
DeviceKey device_key(const compute::device& device);
DeviceProfile device_profile(const DeviceKey& key);
DeviceProfile device_profile(const compute::device& device);
const char* class_name(DeviceClass device_class);

}  // namespace clrt
