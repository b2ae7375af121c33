// The wavefront's queues on one device. Every buffer is sized by the queue capacity (rays per
// queue) and the shadow samples per shading point, never by the image or the ray depth.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "device/device_context.hpp"
#include "render/device_buffer.hpp"
#include "render/stage_args.hpp"
#include "render/wave_sizes.hpp"

namespace clrt {

// The queues, each once, as X(member, element, length in elements of WaveSizes s, name):
//   rays, next_rays   this pass's queue, the next one
//   hits, colour      hits[i] and colour[i] of rays[i]
//   spawn_*           CLRT_CHILD_SLOTS per ray (reflection, refraction), compacted into next_rays
//   shadow_*          shadow samples per ray of a shade chunk, compacted into shadow_queue
//   visible           visible[j] of shadow_queue[j]
//   shade_*           shading class by class: a chunk's ray indices, every class's flags (one
//                     set per class, class_flag_stride apart) and one class's compacted order
//                     (kernels/sort_hits.cl)
#define CLRT_WAVE_QUEUE_BUFFERS(X)                                                 \
  X(rays, dev::Ray, s.capacity, "ray queue")                                      \
  X(next_rays, dev::Ray, s.capacity, "next ray queue")                            \
  X(hits, dev::Hit, s.capacity, "hit")                                            \
  X(colour, dev::f4, s.capacity, "ray colour")                                    \
  X(spawn_slots, dev::Ray, CLRT_CHILD_SLOTS * s.capacity, "spawned ray slot")     \
  X(spawn_flags, cl_uint, CLRT_CHILD_SLOTS * s.capacity, "spawned ray flag")      \
  X(shadow_slots, dev::ShadowRay, s.shadow_buffer_slots(), "shadow ray slot")     \
  X(shadow_flags, cl_uint, s.shadow_buffer_slots(), "shadow ray flag")            \
  X(shadow_queue, dev::ShadowRay, s.shadow_buffer_slots(), "shadow ray queue")    \
  X(visible, dev::f4, s.shadow_buffer_slots(), "shadow visibility")                \
  X(shade_indices, cl_uint4, s.shade_chunk, "shading index")                       \
  X(shade_flags, cl_uint, CLRT_SHADE_CLASSES * s.class_flag_stride, "shading class flag")                     \
  X(shade_order, cl_uint4, s.shade_chunk, "shading order")

class WaveQueues {
 public:
  WaveQueues(DeviceContext& device, const WaveSizes& sizes);
  // What the constructor allocates for `sizes`.
  static std::vector<DeviceBuffer> buffers(const WaveSizes& sizes);

  std::uint32_t capacity() const { return capacity_; }
  // Rays shaded per shade launch: their shadow slots fill the shadow buffers.
  std::uint32_t shade_chunk() const { return shade_chunk_; }
  std::size_t shadow_slots_per_chunk() const { return shadow_slots_; }
  std::uint32_t class_flag_stride() const { return class_flag_stride_; }
  std::uint64_t bytes() const { return bytes_; }

  // The next pass's rays become the current ones.
  void advance() { std::swap(rays, next_rays); }

  CLRT_WAVE_QUEUE_BUFFERS(CLRT_BUFFER_MEMBER)
  // Class k's flag set in shade_flags, as a buffer of its own for the compaction.
  std::array<Global<cl_uint>, CLRT_SHADE_CLASSES> class_flags;

 private:
  std::uint32_t capacity_, shade_chunk_, class_flag_stride_;
  std::size_t shadow_slots_;
  std::uint64_t bytes_ = 0;
};

}  // namespace clrt
