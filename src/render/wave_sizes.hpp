// How large a device's queues are for a render: the numbers WavefrontRenderer allocates by, and
// that the checks before a render (render_limits.hpp) hold against the device's limits.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace clrt {

struct WaveSizes {
  std::uint64_t capacity = 0;     // rays per queue: the wavefront, at least one pixel's samples
  std::uint64_t shade_chunk = 0;  // rays shaded per launch, so that their shadow slots fit
  std::uint64_t shadow_slots = 0; // shade_chunk * shadow samples per shading point
  std::uint64_t wave_pixels = 0;  // pixels per wave before any overflow halves it

  struct Buffer {
    std::string what;  // as DeviceContext::allocate names it in errors
    std::uint64_t bytes;
  };
  // The per-device buffers whose size grows with the queues (not the scene tables).
  std::vector<Buffer> buffers() const;
};

// In 64 bits, so that no product wraps before the limits are checked.
WaveSizes wave_sizes(std::uint64_t wavefront, std::uint64_t samples, std::uint64_t shadow_samples);

}  // namespace clrt
