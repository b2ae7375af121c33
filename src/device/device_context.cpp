#include "device/device_context.hpp"

#include <optional>
#include <sstream>
#include <vector>

#include "device/background_store.hpp"
#include "device/device_profile.hpp"
#include "device/kernel_args.hpp"
#include "device/program_cache.hpp"

namespace clrt {

namespace {

std::string mib(std::size_t bytes) {
  std::ostringstream out;
  out.precision(1);
  out << std::fixed << static_cast<double>(bytes) / (1024.0 * 1024.0) << " MiB";
  return out.str();
}

}  // namespace

DeviceContext::DeviceContext(const DeviceEntry& entry)
    : DeviceContext(entry, compute::context(entry.device)) {}

DeviceContext::DeviceContext(const DeviceEntry& entry, const compute::context& context)
    : entry_(entry),
      context_(context),
      queue_(context_, entry.device, compute::command_queue::enable_profiling) {}

DeviceContext DeviceContext::lane() const { return DeviceContext(entry_, context_); }

namespace {

// Everything a compiled binary depends on besides the driver's own state.
std::string program_identity(const compute::device& device, const std::string& source,
                             const std::string& options) {
  const compute::platform platform = device.platform();
  return platform.name() + "\n" + platform.version() + "\n" + device.name() + "\n" +
         device.version() + "\n" + device.driver_version() + "\n" + options + "\n" + source;
}

// A cache entry's payload: the argument information the driver reported for the program built
// from source (a length line, then the text), then the binary.
std::string cache_payload(const compute::program& program) {
  const std::string signatures = program_signatures(program);
  const std::vector<unsigned char> binary = program.binary();
  return std::to_string(signatures.size()) + "\n" + signatures +
         std::string(binary.begin(), binary.end());
}

// The cached binary, built; none if there is none or the driver refuses it (then it is dropped).
std::optional<compute::program> build_cached(const ProgramCache& cache,
                                             const compute::context& context,
                                             const compute::device& device,
                                             const std::string& options) {
  const std::optional<std::string> payload = cache.load();
  if (!payload) return std::nullopt;
  const std::size_t newline = payload->find('\n');
  std::size_t signature_size = 0;
  if (newline != std::string::npos && newline > 0 && newline <= 9 &&
      payload->find_first_not_of("0123456789") == newline)
    signature_size = std::stoul(payload->substr(0, newline));
  const std::size_t binary_at = newline + 1 + signature_size;
  if (newline != std::string::npos && binary_at < payload->size()) {
    try {
      compute::program program = compute::program::create_with_binary(
          reinterpret_cast<const unsigned char*>(payload->data() + binary_at),
          payload->size() - binary_at, context);
      if (clBuildProgram(program.get(), 1, &device.get(), options.c_str(), nullptr, nullptr) ==
          CL_SUCCESS) {
        adopt_signatures(program, payload->substr(newline + 1, signature_size));
        return program;
      }
    } catch (const compute::opencl_error&) {
    }
  }
  cache.forget();
  return std::nullopt;
}

// PoCL keeps every kernel it compiles in a cache of its own, and asked for a program's binary it
// compiles each of the program's kernels once more, in a form for any work-group size: 9.5 s of
// a 14 s first render of reflect.ray, where a warm build from source costs its cache lookup,
// some 30 ms more than loading clrt's binary. So its binaries are made in the background.
bool driver_keeps_compiled_kernels(const compute::device& device) {
  return device.platform().name() == "Portable Computing Language";
}

}  // namespace

compute::program DeviceContext::build(const std::string& source, const std::string& options,
                                      const CompileNotice& compiling) const {
  const std::string all_options =
      device_profile(entry_.device).program_options + (options.empty() ? "" : " " + options);
  std::optional<ProgramCache> cache;
  if (const auto folder = ProgramCache::folder_from_environment())
    cache.emplace(*folder, program_identity(entry_.device, source, all_options));
  if (cache)
    if (auto program = build_cached(*cache, context_, entry_.device, all_options)) return *program;
  const bool in_background = cache && driver_keeps_compiled_kernels(entry_.device) &&
                             !ProgramCache::named_by_environment();
  if (compiling) compiling(cache && !in_background);
  compute::program program = compute::program::create_with_source(source, context_);
  const cl_int status = clBuildProgram(program.get(), 1, &entry_.device.get(), all_options.c_str(),
                                       nullptr, nullptr);
  if (status != CL_SUCCESS) {
    throw DeviceError("kernel build failed on " + name() + " (" +
                      compute::opencl_error::to_string(status) + "); build log:\n" +
                      program.build_log());
  }
  if (in_background)
    defer_program_store(cache->file(), entry_.device, options, source);
  else if (cache)
    cache->store(cache_payload(program));
  return program;
}

bool DeviceContext::works_in_host_memory() const {
  return (entry_.device.type() & CL_DEVICE_TYPE_CPU) &&
         entry_.device.get_info<cl_bool>(CL_DEVICE_HOST_UNIFIED_MEMORY);
}

namespace {

void CL_CALLBACK release_host_memory(cl_mem, void* owner) {
  delete static_cast<std::shared_ptr<const void>*>(owner);
}

}  // namespace

compute::buffer DeviceContext::share_host_memory(const void* data, std::size_t bytes,
                                                 const std::string& what,
                                                 std::shared_ptr<const void> owner) const {
  const auto refuse = [&](const std::string& why) {
    return DeviceError("cannot use the " + what + " (" + mib(bytes) + ") on " + name() + ": " + why);
  };
  compute::buffer buffer;
  try {
    buffer = compute::buffer(context_, bytes, CL_MEM_READ_ONLY | CL_MEM_USE_HOST_PTR,
                             const_cast<void*>(data));
  } catch (const compute::opencl_error& e) {
    throw refuse(e.error_string());
  }
  // OpenCL deletes a buffer once it is released and the commands using it have finished, which
  // may be after clReleaseMemObject returns: the memory under it must stay until then.
  auto* held = new std::shared_ptr<const void>(std::move(owner));
  const cl_int status = clSetMemObjectDestructorCallback(buffer.get(), release_host_memory, held);
  if (status != CL_SUCCESS) {
    delete held;
    throw refuse(compute::opencl_error::to_string(status));
  }
  return buffer;
}

namespace {

// A zero-size buffer is invalid in OpenCL; one element is kept so that empty tables still bind.
std::size_t buffer_size(std::size_t bytes) { return bytes == 0 ? 16 : bytes; }

}  // namespace

compute::buffer DeviceContext::create_buffer(std::size_t bytes, const std::string& what,
                                             cl_mem_flags flags, const void* host) const {
  const std::size_t max_alloc = entry_.device.get_info<cl_ulong>(CL_DEVICE_MAX_MEM_ALLOC_SIZE);
  const auto refuse = [&](const std::string& why) {
    return DeviceError("cannot allocate the " + what + " buffer (" + mib(bytes) + ") on " + name() +
                       ": " + why);
  };
  if (bytes > max_alloc)
    throw refuse("larger than the device's largest allocation (" + mib(max_alloc) +
                 "); lower --wavefront");
  try {
    return compute::buffer(context_, buffer_size(bytes), flags, const_cast<void*>(host));
  } catch (const compute::opencl_error& e) {
    throw refuse(e.error_string());
  }
}

compute::buffer DeviceContext::allocate(std::size_t bytes, const std::string& what) const {
  compute::buffer buffer = create_buffer(bytes, what);
  // Written once on the device before any kernel sees it, and waited for: a process that
  // rendered many times on Intel's CPU runtime crashed inside its kernels now and then (nearly
  // always with one context for all renders) when the buffers were first written by kernels of
  // other queues; zero-filled, none did (docs/devices.md). It also means no kernel can ever read
  // what another process left in that memory.
  const cl_uchar zero = 0;
  compute::command_queue queue = queue_;
  queue.enqueue_fill_buffer(buffer, &zero, sizeof zero, 0, buffer_size(bytes)).wait();
  return buffer;
}

compute::buffer DeviceContext::allocate_copy(const void* data, std::size_t bytes,
                                             const std::string& what) const {
  if (bytes == 0) return allocate(bytes, what);
  // Copied by clCreateBuffer itself, not by a write queued after it: with another process
  // computing beside it, Intel's CPU runtime let kernels read such a freshly written buffer as
  // zeros or garbage in 4-10 of 100 runs of 30 renders, and in 0 of 200 this way (docs/devices.md).
  return create_buffer(bytes, what, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, data);
}

}  // namespace clrt
