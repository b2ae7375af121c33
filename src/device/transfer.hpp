// Typed device buffers to and from host tables.
#pragma once

#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "device/device_context.hpp"
#include "device/kernel_args.hpp"
#include "math/page_aligned_allocator.hpp"

namespace clrt {

// A buffer holding a copy of `table` (an empty table still gets a buffer, so that it binds).
template <class T, class A>
Global<T> upload(DeviceContext& device, const std::vector<T, A>& table, const std::string& what) {
  return Global<T>(device.allocate_copy(table.data(), sizeof(T) * table.size(), what));
}

// A read-only buffer of `table`, which `owner` holds: on a device that works in host memory,
// `table` itself (it must stay unchanged; `owner` is kept until the runtime deletes the buffer;
// page alignment is what lets a driver use it in place), elsewhere a copy.
template <class T>
Global<const T> share(DeviceContext& device, const std::vector<T, PageAlignedAllocator<T>>& table,
                      const std::string& what, const std::shared_ptr<const void>& owner) {
  if (table.empty() || !device.works_in_host_memory()) return upload(device, table, what);
  return Global<const T>(
      device.share_host_memory(table.data(), sizeof(T) * table.size(), what, owner));
}

// An uninitialised buffer of `count` Ts.
template <class T>
Global<T> allocate(DeviceContext& device, std::size_t count, const std::string& what) {
  return Global<T>(device.allocate(sizeof(T) * count, what));
}

// The first `count` elements of `buffer`, after everything queued before (a blocking read).
template <class T>
std::vector<std::remove_const_t<T>> download(DeviceContext& device, const Global<T>& buffer,
                                             std::size_t count) {
  std::vector<std::remove_const_t<T>> data(count);
  if (count)
    device.queue().enqueue_read_buffer(buffer.buffer, 0, sizeof(T) * count, data.data());
  return data;
}

}  // namespace clrt
