// How large a wave is on a device for a render: the numbers the integrators allocate by, and
// that the checks before a render (render_limits.hpp) hold against the device's limits.
#pragma once

#include <algorithm>
#include <cstdint>

namespace clrt {

struct WaveSizes {
  std::uint64_t capacity = 0;     // rays per queue: the wavefront, at least one pixel's samples
  std::uint64_t shade_chunk = 0;  // rays shaded per launch, so that their shadow slots fit
  std::uint64_t shadow_slots = 0; // shade_chunk * shadow samples per shading point
  // Between the shading classes' flag sets: shade_chunk rounded up to kClassFlagAlignment.
  std::uint64_t class_flag_stride = 0;
  std::uint64_t wave_pixels = 0;  // the most pixels a wave holds: a round of one sample each

  // An OpenCL buffer cannot be empty, so a scene without shadow rays still gets one slot.
  std::uint64_t shadow_buffer_slots() const { return std::max<std::uint64_t>(1, shadow_slots); }
};

// Flags per alignment step of the class flag sets: 4096 bytes, a multiple of every device's
// CL_DEVICE_MEM_BASE_ADDR_ALIGN (at most 4096 bits on today's GPUs), so that each set can be
// a sub-buffer of its own, which the compaction reads from its start.
constexpr std::uint64_t kClassFlagAlignment = 1024;

// In 64 bits, so that no product wraps before the limits are checked.
WaveSizes wave_sizes(std::uint64_t wavefront, std::uint64_t samples, std::uint64_t shadow_samples);

}  // namespace clrt
