#include "render/wave_queues.hpp"

#include <algorithm>

#include "device/transfer.hpp"

namespace clrt {

template <class T>
Global<T> WaveQueues::make(DeviceContext& device, std::size_t count, const char* what) {
  bytes_ += sizeof(T) * count;
  return allocate<T>(device, count, what);
}

WaveQueues::WaveQueues(DeviceContext& device, const WaveSizes& sizes, std::uint32_t shadow_samples)
    : capacity_(static_cast<std::uint32_t>(sizes.capacity)),
      shadow_samples_(shadow_samples),
      shade_chunk_(static_cast<std::uint32_t>(sizes.shade_chunk)) {
  const std::size_t shadows = std::max<std::size_t>(1, shadow_slots_per_chunk());
  rays = make<dev::Ray>(device, capacity_, "ray queue");
  next_rays = make<dev::Ray>(device, capacity_, "next ray queue");
  hits = make<dev::Hit>(device, capacity_, "hit");
  colour = make<dev::f4>(device, capacity_, "ray colour");
  spawn_slots = make<dev::Ray>(device, 2 * std::size_t{capacity_}, "spawned ray slot");
  spawn_flags = make<cl_uint>(device, 2 * std::size_t{capacity_}, "spawned ray flag");
  shadow_slots = make<dev::ShadowRay>(device, shadows, "shadow ray slot");
  shadow_flags = make<cl_uint>(device, shadows, "shadow ray flag");
  shadow_queue = make<dev::ShadowRay>(device, shadows, "shadow ray queue");
  visible = make<dev::f4>(device, shadows, "shadow visibility");
}

}  // namespace clrt
