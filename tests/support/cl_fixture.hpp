// What kernel tests share: one OpenCL device, context and queue per test binary, cached program
// builds, and typed upload/download of host vectors.
#pragma once

#include <string>
#include <vector>

#include "device/device_context.hpp"

namespace clrt::test {

// The first CPU device (PoCL in CI), created on first use and kept for the whole binary.
DeviceContext& device();

// Builds (once per binary, cached by text) a test program: `text` may #include any file of
// kernels/ by its path, e.g. #include "geometry/shapes.h".
compute::program& test_program(const std::string& text);

// The renderer's own program (every kernels/*.cl stage), built once per binary.
compute::program& renderer_program();

template <class T>
compute::buffer upload(const std::vector<T>& data, const std::string& what = "test input") {
  compute::buffer buffer = device().allocate(sizeof(T) * data.size(), what);
  if (!data.empty())
    device().queue().enqueue_write_buffer(buffer, 0, sizeof(T) * data.size(), data.data());
  return buffer;
}

template <class T>
std::vector<T> download(const compute::buffer& buffer, std::size_t count) {
  std::vector<T> data(count);
  if (count) device().queue().enqueue_read_buffer(buffer, 0, sizeof(T) * count, data.data());
  return data;
}

// Runs `kernel` over `count` work-items (padded to the renderer's local size) and waits.
void run(compute::kernel& kernel, std::size_t count);

}  // namespace clrt::test
