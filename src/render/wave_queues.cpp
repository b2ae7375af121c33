#include "render/wave_queues.hpp"

#include "device/transfer.hpp"

namespace clrt {

std::vector<DeviceBuffer> WaveQueues::buffers(const WaveSizes& s) {
  return {CLRT_WAVE_QUEUE_BUFFERS(CLRT_BUFFER_DESCRIBE)};
}

WaveQueues::WaveQueues(DeviceContext& device, const WaveSizes& s)
    : capacity_(static_cast<std::uint32_t>(s.capacity)),
      shade_chunk_(static_cast<std::uint32_t>(s.shade_chunk)),
      shadow_slots_(static_cast<std::size_t>(s.shadow_slots)) {
  CLRT_WAVE_QUEUE_BUFFERS(CLRT_BUFFER_ALLOCATE)
  for (const DeviceBuffer& b : buffers(s)) bytes_ += b.bytes;
}

}  // namespace clrt
