// What the renderer launches with on each class of device. Everything here is either a launch
// parameter or one fixed program-option string per class, so that a device's program text and
// options never depend on the scene and the kernel cache stays warm across scenes.
#pragma once

#include <cstdint>
#include <string>

#include "device/opencl.hpp"

namespace clrt {

enum class DeviceClass { Cpu, Gpu, Other };

struct DeviceTuning {
  DeviceClass device_class = DeviceClass::Cpu;
  std::size_t local_size = 64;           // work-items per work-group, every kernel
  std::uint32_t wavefront = 1u << 14;    // rays per queue when the user names none
  // Waves in flight on the device, each on its own command queue with its own queues: while
  // one waits for the host, the other's kernels run.
  std::uint32_t lanes = 2;
  std::uint32_t megakernel_depth = 32;   // deepest ray tree the megakernel's private stack holds

  // The options that make the program of this class (see kernels/megakernel.cl).
  std::string program_options() const;
};

DeviceClass classify(const compute::device& device);
DeviceTuning tuning_for(DeviceClass device_class);
// The class's tuning, adjusted for the implementation where measurements say so.
DeviceTuning tuning_for(const compute::device& device);
const char* class_name(DeviceClass device_class);

}  // namespace clrt
