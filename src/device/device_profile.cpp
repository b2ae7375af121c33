#include "device/device_profile.hpp"

#include <optional>

namespace clrt {
namespace {

constexpr std::nullopt_t kAny = std::nullopt;
constexpr const char* kAnyPlatform = nullptr;

// One row of the table: the devices it applies to (an empty field matches every device) and
// what it sets for them. Every matching row applies, in order: a value of 0 leaves what the
// rows before set, and its options are added after theirs.
struct ProfileRow {
  std::optional<DeviceClass> device_class;
  const char* platform;
  std::optional<bool> rounds_divide_sqrt;
  std::size_t local_size;
  std::uint32_t wavefront;
  std::uint32_t lanes;
  const char* program_options;
};

// CPU (measured on PoCL, 2 cores; docs/experiments.md): 16384 rays per queue keep the queues in
// the caches; local size 64 is in the 64-256 band where every kernel measured best, and the
// smallest of it keeps PoCL's work-group functions few and small.
//
// GPU (none here to measure; the reasoning): 1M rays per queue give a large GPU (100+ compute
// units of 2048 resident work-items) a few full waves of work per launch to hide memory latency,
// in about 0.5 GB of queues; local size 128 is a multiple of both NVIDIA's 32-wide warps and
// AMD's 64-wide wavefronts and leaves the scheduler room.
//
// Other accelerators get the GPU's queue sizes with the CPU's local size: a middle ground.
//
// Intel's CPU runtime runs a work-group of 16 or more work-items as 16-wide SIMD: the
// traversal and shading loops then diverge, and every lane waits for the longest (at local size
// 64, 1.8 Mrays/s on the SPD teapot against 10.4 at 8; docs/experiments.md, "Two
// implementations"). Groups of 8 keep its compiler off that path.
//
// Division and sqrt are correctly rounded wherever the device can: with FP_CONTRACT off and
// kernels/math/exact.h, every operation then has the bits IEEE 754 gives it.
//
// PoCL's prefetch() is empty; Clang's own builtin, which only PoCL's compiler takes here, makes
// incoherent rays 20% faster there (kernels/geometry/bvh_stack.h).
//
// Oclgrind is for checking the code as written: unoptimised, since its interpreter runs some of
// what its own optimiser makes wrongly (triangle hits on rays that miss), and without forced
// inlining, whose output it cannot run (kernels/shared/common.h).
const ProfileRow kProfileTable[] = {
    // Argument information lets the host check every binding against the kernel's signature.
    {kAny, kAnyPlatform, kAny, 0, 0, 2, "-cl-std=CL1.2 -cl-kernel-arg-info"},
    {DeviceClass::Cpu, kAnyPlatform, kAny, 64, 1u << 14, 0, ""},
    {DeviceClass::Gpu, kAnyPlatform, kAny, 128, 1u << 20, 0, ""},
    {DeviceClass::Other, kAnyPlatform, kAny, 64, 1u << 20, 0, ""},
    {DeviceClass::Cpu, "Intel(R) OpenCL", kAny, 8, 0, 0, ""},
    {kAny, kAnyPlatform, true, 0, 0, 0, "-cl-fp32-correctly-rounded-divide-sqrt"},
    {kAny, "Portable Computing Language", kAny, 0, 0, 0, "-DCLRT_CLANG_PREFETCH"},
    {kAny, "Oclgrind", kAny, 0, 0, 0, "-cl-opt-disable -DCLRT_NO_FORCED_INLINE"},
};

bool matches(const ProfileRow& row, const DeviceKey& key) {
  return (!row.device_class || *row.device_class == key.device_class) &&
         (!row.platform || key.platform == row.platform) &&
         (!row.rounds_divide_sqrt || *row.rounds_divide_sqrt == key.rounds_divide_sqrt);
}

}  // namespace

DeviceClass classify(const compute::device& device) {
  const cl_device_type type = device.type();
  if (type & CL_DEVICE_TYPE_CPU) return DeviceClass::Cpu;
  if (type & CL_DEVICE_TYPE_GPU) return DeviceClass::Gpu;
  return DeviceClass::Other;
}

DeviceKey device_key(const compute::device& device) {
  DeviceKey key;
  key.device_class = classify(device);
  key.platform = device.platform().name();
  key.rounds_divide_sqrt = (device.get_info<cl_device_fp_config>(CL_DEVICE_SINGLE_FP_CONFIG) &
                            CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) != 0;
  return key;
}

DeviceProfile device_profile(const DeviceKey& key) {
  DeviceProfile profile;
  profile.device_class = key.device_class;
  for (const ProfileRow& row : kProfileTable) {
    if (!matches(row, key)) continue;
    if (row.local_size) profile.local_size = row.local_size;
    if (row.wavefront) profile.wavefront = row.wavefront;
    if (row.lanes) profile.lanes = row.lanes;
    if (*row.program_options)
      profile.program_options +=
          (profile.program_options.empty() ? "" : " ") + std::string(row.program_options);
  }
  return profile;
}

DeviceProfile device_profile(const compute::device& device) {
  return device_profile(device_key(device));
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
