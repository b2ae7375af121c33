// Stable compaction of flagged fixed-size records on the device (kernels/compact.cl).
#pragma once

#include <cstddef>
#include <cstdint>

#include "device/device_context.hpp"

namespace clrt {

class Compactor {
 public:
  // `max_slots`: the most slots one call will compact (sizes the chunk-offset buffer).
  Compactor(DeviceContext& device, const compute::program& program, std::size_t max_slots);

  // Copies the records of `in` whose flag is set, in order, to the front of `out` (at most
  // `capacity` of them), and returns how many were flagged: the only value read back to the
  // host. `record_bytes` is a multiple of 16.
  std::uint32_t compact(const compute::buffer& in, const compute::buffer& flags, std::size_t slots,
                        std::size_t record_bytes, const compute::buffer& out,
                        std::size_t capacity);

  // The same, without waiting: the count is left in total() for kernels that read it there.
  void enqueue(const compute::buffer& in, const compute::buffer& flags, std::size_t slots,
               std::size_t record_bytes, const compute::buffer& out, std::size_t capacity);
  std::uint32_t read_total();

  // One uint on the device: the flagged count of the last call.
  const compute::buffer& total() const { return total_; }

  // Slots per work-item: large enough that each work-item streams a long run (no barriers or
  // atomics needed), small enough that 2 cores still get many work-items per launch.
  static constexpr std::uint32_t kChunk = 256;

  // The events of the last compact() call's launches, in order, for profiling.
  const compute::event& count_event() const { return events_[0]; }
  const compute::event& scan_event() const { return events_[1]; }
  const compute::event& scatter_event() const { return events_[2]; }

 private:
  DeviceContext& device_;
  compute::kernel count_, scan_, scatter_;
  compute::buffer chunk_counts_, total_;
  compute::event events_[3];
};

}  // namespace clrt
