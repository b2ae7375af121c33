// One OpenCL device with its context and an in-order, profiling-enabled command queue, and the
// checked ways to build programs and allocate buffers on it.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "device/device_select.hpp"
#include "device/opencl.hpp"

namespace clrt {

// Told before a program is compiled from source: `first_run` when clrt's program cache was
// asked and lacks it; false when the driver's own cache decides (PoCL's: it may be quick, and the
// entry is stored in the background afterwards).
using CompileNotice = std::function<void(bool first_run)>;

class DeviceContext {
 public:
  explicit DeviceContext(const DeviceEntry& entry);

  // Another command queue on the same device and context: buffers and programs are shared, and
  // the device may run the two queues' commands in any interleaving (a lane of work).
  DeviceContext lane() const;

  const DeviceEntry& entry() const { return entry_; }
  const compute::device& device() const { return entry_.device; }
  compute::context& context() { return context_; }
  compute::command_queue& queue() { return queue_; }
  std::string name() const { return entry_.device.name(); }

  // Builds `source` (already assembled, see kernel_source.hpp) with the options of the device's
  // profile (device_profile.hpp) and then `options`, from the program cache when it
  // holds it; else `compiling` is called first, since compiling takes seconds where loading
  // takes milliseconds. A failure throws DeviceError with the device's whole build log.
  compute::program build(const std::string& source, const std::string& options = "",
                         const CompileNotice& compiling = {}) const;

  // A device buffer of `bytes`, all zeros, for kernels to write; `what` names it in the error
  // when the device refuses.
  compute::buffer allocate(std::size_t bytes, const std::string& what) const;
  // A device buffer holding a copy of `bytes` of host memory at `data` (written before this
  // returns, so not zero-filled first).
  compute::buffer allocate_copy(const void* data, std::size_t bytes, const std::string& what) const;

  // Whether the device computes in the host's memory (a CPU device): then a page-aligned host
  // table can be its buffer as it lies.
  bool works_in_host_memory() const;
  // A read-only buffer over `bytes` of host memory at `data` (page-aligned), without a copy.
  // `owner` keeps that memory alive until the runtime has deleted the buffer, which OpenCL lets
  // it do after clReleaseMemObject returns (its destructor callback says when).
  compute::buffer share_host_memory(const void* data, std::size_t bytes, const std::string& what,
                                    std::shared_ptr<const void> owner) const;

 private:
  DeviceEntry entry_;
  compute::context context_;
  compute::command_queue queue_;

  DeviceContext(const DeviceEntry& entry, const compute::context& context);
  // A buffer of `bytes` as the device gives it (`host` as clCreateBuffer takes it with `flags`),
  // its refusal worded for `what`.
  compute::buffer create_buffer(std::size_t bytes, const std::string& what,
                                cl_mem_flags flags = CL_MEM_READ_WRITE,
                                const void* host = nullptr) const;
};

}  // namespace clrt
