#include "render/compactor.hpp"

#include "device/launch.hpp"

namespace clrt {

Compactor::Compactor(DeviceContext& device, const compute::program& program, std::size_t max_slots)
    : device_(device),
      count_(program, "compact_count"),
      scan_(program, "compact_scan"),
      scatter_(program, "compact_scatter"),
      chunk_counts_(device.allocate((max_slots / kChunk + 1) * sizeof(std::uint32_t),
                                    "compaction chunk counts")),
      total_(device.allocate(sizeof(std::uint32_t), "compaction total")) {}

std::uint32_t Compactor::compact(const compute::buffer& in, const compute::buffer& flags,
                                 std::size_t slots, std::size_t record_bytes,
                                 const compute::buffer& out, std::size_t capacity) {
  if (slots == 0) return 0;
  enqueue(in, flags, slots, record_bytes, out, capacity);
  return read_total();
}

void Compactor::enqueue(const compute::buffer& in, const compute::buffer& flags, std::size_t slots,
                        std::size_t record_bytes, const compute::buffer& out,
                        std::size_t capacity) {
  auto& queue = device_.queue();
  const auto n = static_cast<std::uint32_t>(slots);
  const std::uint32_t chunks = (n + kChunk - 1) / kChunk;
  count_.set_args(flags, n, kChunk, chunk_counts_);
  events_[0] = launch(queue, count_, chunks);
  scan_.set_args(chunk_counts_, chunks, total_);
  events_[1] = launch(queue, scan_, 1);
  scatter_.set_args(in, flags, n, kChunk, static_cast<std::uint32_t>(record_bytes / 16),
                    chunk_counts_, out, static_cast<std::uint32_t>(capacity));
  events_[2] = launch(queue, scatter_, chunks);
}

std::uint32_t Compactor::read_total() {
  std::uint32_t total = 0;
  device_.queue().enqueue_read_buffer(total_, 0, sizeof(total), &total);
  return total;
}

}  // namespace clrt
