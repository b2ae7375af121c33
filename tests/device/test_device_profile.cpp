// The device profile table: what each class and platform builds and launches with, as
// docs/devices.md states it, and that every program on the test device is built with its
// profile's options.
#include <catch2/catch.hpp>

#include <string>

#include "cl_fixture.hpp"
#include "device/device_profile.hpp"

using namespace clrt;

namespace {

const std::string kEveryProgram = "-cl-std=CL1.2 -cl-kernel-arg-info";

bool has(const std::string& options, const std::string& option) {
  return (" " + options + " ").find(" " + option + " ") != std::string::npos;
}

}  // namespace

TEST_CASE("each device class launches with the defaults docs/devices.md gives it", "[device]") {
  struct Row {
    DeviceKey key;
    std::size_t local_size;
    std::uint32_t wavefront;
  };
  for (const Row& row : {Row{{DeviceClass::Cpu, "Portable Computing Language", true}, 64, 16384},
                         Row{{DeviceClass::Cpu, "Intel(R) OpenCL", true}, 8, 16384},
                         Row{{DeviceClass::Gpu, "NVIDIA CUDA", true}, 128, 1u << 20},
                         Row{{DeviceClass::Gpu, "Intel(R) OpenCL", true}, 128, 1u << 20},
                         Row{{DeviceClass::Other, "Oclgrind", false}, 64, 1u << 20}}) {
    INFO(class_name(row.key.device_class) << " on " << row.key.platform);
    const DeviceProfile profile = device_profile(row.key);
    CHECK(profile.device_class == row.key.device_class);
    CHECK(profile.local_size == row.local_size);
    CHECK(profile.wavefront == row.wavefront);
    CHECK(profile.lanes == 2);
  }
}

TEST_CASE("every program's options come first, then the device's and its platform's",
          "[device]") {
  const auto options = [](DeviceClass c, const char* platform, bool rounds) {
    return device_profile(DeviceKey{c, platform, rounds}).program_options;
  };
  CHECK(options(DeviceClass::Gpu, "NVIDIA CUDA", false) == kEveryProgram);
  CHECK(options(DeviceClass::Gpu, "NVIDIA CUDA", true) ==
        kEveryProgram + " -cl-fp32-correctly-rounded-divide-sqrt");
  CHECK(options(DeviceClass::Cpu, "Portable Computing Language", true) ==
        kEveryProgram + " -cl-fp32-correctly-rounded-divide-sqrt -DCLRT_CLANG_PREFETCH");
  CHECK(options(DeviceClass::Other, "Oclgrind", false) ==
        kEveryProgram + " -cl-opt-disable -DCLRT_NO_FORCED_INLINE");
  // A platform's own options are its alone, whatever the class.
  for (const DeviceClass c : {DeviceClass::Cpu, DeviceClass::Gpu, DeviceClass::Other}) {
    INFO(class_name(c));
    CHECK_FALSE(has(options(c, "Intel(R) OpenCL", true), "-DCLRT_CLANG_PREFETCH"));
    CHECK_FALSE(has(options(c, "Intel(R) OpenCL", true), "-cl-opt-disable"));
    CHECK(has(options(c, "Portable Computing Language", false), "-DCLRT_CLANG_PREFETCH"));
    CHECK(has(options(c, "Oclgrind", false), "-DCLRT_NO_FORCED_INLINE"));
  }
}

TEST_CASE("a program on the test device is built with its profile's options, then its own",
          "[device]") {
  const compute::device& device = test::device().device();
  const DeviceProfile profile = device_profile(device);
  CHECK(profile.device_class == classify(device));
  CHECK(profile.program_options == device_profile(device_key(device)).program_options);
  const compute::program program =
      test::device().build("__kernel void f(__global int* x) { x[0] = CLRT_TEST_VALUE; }",
                           "-DCLRT_TEST_VALUE=3");
  CHECK(program.get_build_info<std::string>(CL_PROGRAM_BUILD_OPTIONS, device) ==
        profile.program_options + " -DCLRT_TEST_VALUE=3");
}
