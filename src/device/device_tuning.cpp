#include "device/device_tuning.hpp"

namespace clrt {

DeviceClass classify(const compute::device& device) {
  const cl_device_type type = device.type();
  if (type & CL_DEVICE_TYPE_CPU) return DeviceClass::Cpu;
  if (type & CL_DEVICE_TYPE_GPU) return DeviceClass::Gpu;
  return DeviceClass::Other;
}

// CPU (measured on PoCL, 2 cores; docs/experiments.md): 16384 rays per queue keep
// the queues in the caches; local size 64 is in the 64-256 band where every kernel measured
// best, and the smallest of it keeps PoCL's work-group functions few and small. The
// megakernel's stack lives in the caches, so a deep one costs nothing until it is used.
//
// GPU (none here to measure; the reasoning): 1M rays per queue give a large GPU (100+ compute
// units of 2048 resident work-items) a few full waves of work per launch to hide memory latency,
// in about 0.5 GB of queues; local size 128 is a multiple of both NVIDIA's 32-wide warps and
// AMD's 64-wide wavefronts and leaves the scheduler room; the megakernel's private stack spills
// to slow memory on GPUs, so it is kept at 16 levels (more than any shipped scene uses).
//
// Other accelerators get the GPU's queue sizes with the CPU's local size: a middle ground.
DeviceTuning tuning_for(DeviceClass device_class) {
  DeviceTuning t;
  t.device_class = device_class;
  switch (device_class) {
    case DeviceClass::Cpu:
      t.local_size = 64;
      t.wavefront = 1u << 14;
      t.megakernel_depth = 32;
      break;
    case DeviceClass::Gpu:
      t.local_size = 128;
      t.wavefront = 1u << 20;
      t.megakernel_depth = 16;
      break;
    case DeviceClass::Other:
      t.local_size = 64;
      t.wavefront = 1u << 20;
      t.megakernel_depth = 16;
      break;
  }
  return t;
}

// Intel's CPU runtime runs a work-group of 16 or more work-items as 16-wide SIMD: the
// traversal and shading loops then diverge, and every lane waits for the longest (at local size
// 64, 1.8 Mrays/s on the SPD teapot against 10.4 at 8; docs/experiments.md, "Two
// implementations"). Groups of 8 keep its compiler off that path.
DeviceTuning tuning_for(const compute::device& device) {
  DeviceTuning t = tuning_for(classify(device));
  if (t.device_class == DeviceClass::Cpu && device.platform().name() == "Intel(R) OpenCL")
    t.local_size = 8;
  return t;
}

std::string DeviceTuning::program_options() const {
  return "-DCLRT_MEGAKERNEL_DEPTH=" + std::to_string(megakernel_depth);
}

const char* class_name(DeviceClass device_class) {
  switch (device_class) {
    case DeviceClass::Cpu: return "cpu";
    case DeviceClass::Gpu: return "gpu";
    case DeviceClass::Other: return "other";
  }
  return "unknown";
}

}  // namespace clrt
