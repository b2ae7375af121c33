// The wavefront's queues on one device. Every buffer is sized by the queue capacity (rays per
// queue) and the shadow samples per shading point, never by the image or the ray depth.
#pragma once

#include <cstdint>

#include "device/device_context.hpp"
#include "device/kernel_args.hpp"
#include "render/wave_sizes.hpp"

namespace clrt {

class WaveQueues {
 public:
  // Sized as the checks before a render assumed (render/wave_sizes.hpp).
  WaveQueues(DeviceContext& device, const WaveSizes& sizes, std::uint32_t shadow_samples);

  std::uint32_t capacity() const { return capacity_; }
  // Rays shaded per shade launch: their shadow slots fill the shadow buffers.
  std::uint32_t shade_chunk() const { return shade_chunk_; }
  std::size_t shadow_slots_per_chunk() const { return std::size_t{shade_chunk_} * shadow_samples_; }
  std::uint64_t bytes() const { return bytes_; }

  // The next pass's rays become the current ones.
  void advance() { std::swap(rays, next_rays); }

  Global<dev::Ray> rays, next_rays;        // this pass's queue, the next one
  Global<dev::Hit> hits;                   // hits[i] of rays[i]
  Global<dev::f4> colour;                  // colour[i] of rays[i]
  Global<dev::Ray> spawn_slots;            // 2 per ray: reflection, refraction
  Global<cl_uint> spawn_flags;
  Global<dev::ShadowRay> shadow_slots;     // shadow_samples per ray of a shade chunk
  Global<cl_uint> shadow_flags;
  Global<dev::ShadowRay> shadow_queue;     // the compacted shadow rays
  Global<dev::f4> visible;                 // visible[j] of shadow_queue[j]

 private:
  template <class T>
  Global<T> make(DeviceContext& device, std::size_t count, const char* what);

  std::uint32_t capacity_, shadow_samples_, shade_chunk_;
  std::uint64_t bytes_ = 0;
};

}  // namespace clrt
