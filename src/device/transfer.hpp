// Typed device buffers to and from host tables.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include "device/device_context.hpp"
#include "device/kernel_args.hpp"

namespace clrt {

// A buffer holding `table` (an empty table still gets a buffer, so that it binds).
template <class T>
Global<T> upload(DeviceContext& device, const std::vector<T>& table, const std::string& what) {
  compute::buffer buffer = device.allocate(sizeof(T) * table.size(), what);
  if (!table.empty())
    device.queue().enqueue_write_buffer(buffer, 0, sizeof(T) * table.size(), table.data());
  return Global<T>(buffer);
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
