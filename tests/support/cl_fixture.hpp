// What kernel tests share: one OpenCL device, context and queue per test binary, cached program
// builds, and typed upload/download of host vectors.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include "device/device_context.hpp"
#include "device/typed_kernel.hpp"
#include "device/transfer.hpp"
#include "render/render_options.hpp"
#include "render/stage_args.hpp"  // the OpenCL C names of the records kernels take

namespace clrt::test {

// The device the kernel tests run on: CLRT_TEST_DEVICE names it as clrt's --device does
// (tools/gpu_check.sh sets it to `gpu`); unset, the first CPU device (PoCL in CI). Created on
// first use and kept for the whole binary.
DeviceContext& device();
std::string test_device_spec();

// Builds (once per binary, cached by text) a test program: `text` may #include any file of
// kernels/ by its path, e.g. #include "geometry/shapes.h".
compute::program& test_program(const std::string& text);

// The renderer's own program (every kernels/*.cl stage) for a mode's transport model, built once
// per binary and mode, with the motion and texture code (it serves every input alike).
compute::program& renderer_program(RenderMode mode = RenderMode::Trace);

template <class T>
Global<T> upload(const std::vector<T>& data, const std::string& what = "test input") {
  return clrt::upload(device(), data, what);
}

template <class T>
Global<T> allocate(std::size_t count, const std::string& what = "test output") {
  return clrt::allocate<T>(device(), count, what);
}

template <class T>
std::vector<std::remove_const_t<T>> download(const Global<T>& buffer, std::size_t count) {
  return clrt::download(device(), buffer, count);
}

// The local size kernel tests launch with: the test device class's, as the renderer's.
std::size_t local_size();

// Throws std::logic_error naming every mismatch when `kernel`'s signature and `Args` disagree.
void check_binding(const compute::kernel& kernel, const std::vector<ExpectedArg>& expected);

// Launches kernel Args::kName of `program` with `args` over `count` work-items in groups of
// `group_size` and waits. The binding is checked against the kernel's signature first.
template <class Args>
void run(const compute::program& program, const Args& args, std::size_t count,
         std::size_t group_size = local_size()) {
  TypedKernel<Args> kernel(program);
  check_binding(kernel.kernel(), expected_args(args));
  kernel.launch(device().queue(), args, count, group_size);
  device().queue().finish();
}

}  // namespace clrt::test
