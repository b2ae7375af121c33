#include "render/wave_queues.hpp"

#include "device/transfer.hpp"

namespace clrt {

std::vector<DeviceBuffer> WaveQueues::buffers(const WaveSizes& s) {
  return {CLRT_WAVE_QUEUE_BUFFERS(CLRT_BUFFER_DESCRIBE)};
}

WaveQueues::WaveQueues(DeviceContext& device, const WaveSizes& s)
    : capacity_(static_cast<std::uint32_t>(s.capacity)),
      shade_chunk_(static_cast<std::uint32_t>(s.shade_chunk)),
      class_flag_stride_(static_cast<std::uint32_t>(s.class_flag_stride)),
      shadow_slots_(static_cast<std::size_t>(s.shadow_slots)) {
  CLRT_WAVE_QUEUE_BUFFERS(CLRT_BUFFER_ALLOCATE)
  const std::size_t set_bytes = sizeof(cl_uint) * std::size_t{class_flag_stride_};
  if (set_bytes * 8 % device.device().get_info<cl_uint>(CL_DEVICE_MEM_BASE_ADDR_ALIGN) != 0)
    throw DeviceError("the device aligns buffers more coarsely than the shading class flags");
  for (std::size_t k = 0; k < class_flags.size(); ++k)
    class_flags[k] = shade_flags.buffer.create_subbuffer(CL_MEM_READ_WRITE, k * set_bytes, set_bytes);
  for (const DeviceBuffer& b : buffers(s)) bytes_ += b.bytes;
}

}  // namespace clrt
