// Stable compaction of flagged fixed-size records on the device (kernels/compact.cl).
#pragma once

#include <cstddef>
#include <cstdint>

#include "render/launcher.hpp"
#include "render/stage_args.hpp"

namespace clrt {

class Compactor {
 public:
  // `max_slots`: the most slots one call will compact (sizes the chunk-offset buffer).
  Compactor(DeviceContext& device, const compute::program& program, std::size_t max_slots);

  // Copies the records of `in` whose flag is set, in order, to the front of `out` (at most
  // `capacity` of them); the number flagged is left on the device in total(), where kernels
  // read it. Launches are recorded under `pass`.
  template <class Record>
  void enqueue(Launcher& launcher, const Global<Record>& in, const Global<cl_uint>& flags,
               std::size_t slots, const Global<Record>& out, std::size_t capacity,
               std::uint32_t pass) {
    static_assert(sizeof(Record) % sizeof(cl_uint4) == 0, "records move as whole uint4 words");
    enqueue_words(launcher, in.buffer, flags, slots, sizeof(Record) / sizeof(cl_uint4),
                  out.buffer, capacity, pass);
  }

  // Waits for the last count: the one value that crosses to the host, once a pass.
  std::uint32_t read_total();

  // One uint on the device: the flagged count of the last call.
  const Global<cl_uint>& total() const { return total_; }

  // Slots per work-item: large enough that each work-item streams a long run (no barriers or
  // atomics needed), small enough that 2 cores still get many work-items per launch.
  static constexpr std::uint32_t kChunk = 256;

 private:
  void enqueue_words(Launcher& launcher, const compute::buffer& in, const Global<cl_uint>& flags,
                     std::size_t slots, std::size_t words, const compute::buffer& out,
                     std::size_t capacity, std::uint32_t pass);

  DeviceContext& device_;
  TypedKernel<CompactCountArgs> count_;
  TypedKernel<CompactScanArgs> scan_;
  TypedKernel<CompactScatterArgs> scatter_;
  Global<cl_uint> chunk_counts_, total_;
};

}  // namespace clrt
