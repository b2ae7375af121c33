#include "render/wave_queues.hpp"

#include <algorithm>

#include "device/transfer.hpp"

namespace clrt {

template <class T>
Global<T> WaveQueues::make(DeviceContext& device, std::size_t count, const char* what) {
  bytes_ += sizeof(T) * count;
  return allocate<T>(device, count, what);
}

WaveQueues::WaveQueues(DeviceContext& device, std::uint32_t capacity, std::uint32_t shadow_samples)
    : capacity_(capacity),
      shadow_samples_(shadow_samples),
      shade_chunk_(shadow_samples == 0 ? capacity
                                       : std::max<std::uint32_t>(1, capacity / shadow_samples)) {
  const std::size_t shadows = std::max<std::size_t>(1, shadow_slots_per_chunk());
  rays = make<dev::Ray>(device, capacity, "ray queue");
  next_rays = make<dev::Ray>(device, capacity, "next ray queue");
  hits = make<dev::Hit>(device, capacity, "hit");
  colour = make<dev::f4>(device, capacity, "ray colour");
  spawn_slots = make<dev::Ray>(device, 2 * std::size_t{capacity}, "spawned ray slot");
  spawn_flags = make<cl_uint>(device, 2 * std::size_t{capacity}, "spawned ray flag");
  shadow_slots = make<dev::ShadowRay>(device, shadows, "shadow ray slot");
  shadow_flags = make<cl_uint>(device, shadows, "shadow ray flag");
  shadow_queue = make<dev::ShadowRay>(device, shadows, "shadow ray queue");
  visible = make<dev::f4>(device, shadows, "shadow visibility");
}

}  // namespace clrt
