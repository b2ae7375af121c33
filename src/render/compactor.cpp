#include "render/compactor.hpp"

#include "device/transfer.hpp"

namespace clrt {

Compactor::Compactor(DeviceContext& device, const compute::program& program, std::size_t max_slots)
    : device_(device),
      count_(program),
      scan_(program),
      scatter_(program),
      chunk_counts_(allocate<cl_uint>(device, max_slots / kChunk + 1, "compaction chunk counts")),
      total_(allocate<cl_uint>(device, 1, "compaction total")) {}

void Compactor::enqueue_words(Launcher& launcher, const compute::buffer& in,
                              const Global<cl_uint>& flags, std::size_t slots, std::size_t words,
                              const compute::buffer& out, std::size_t capacity,
                              std::uint32_t pass) {
  const auto n = static_cast<cl_uint>(slots);
  const cl_uint chunks = (n + kChunk - 1) / kChunk;
  launcher.launch(count_, {flags, n, kChunk, chunk_counts_}, chunks, pass);
  // One work-item: the chunk count is small (n / chunk), so a serial scan costs microseconds.
  launcher.launch(scan_, {chunk_counts_, chunks, total_}, 1, pass);
  launcher.launch(scatter_,
                  {Global<const cl_uint4>(in), flags, n, kChunk, static_cast<cl_uint>(words),
                   chunk_counts_, Global<cl_uint4>(out), static_cast<cl_uint>(capacity)},
                  chunks, pass);
}

std::uint32_t Compactor::read_total() {
  std::uint32_t total = 0;
  device_.queue().enqueue_read_buffer(total_.buffer, 0, sizeof(total), &total);
  return total;
}

}  // namespace clrt
