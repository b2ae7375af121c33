#include "render/wave_sizes.hpp"

#include <algorithm>

#include "shared/ray.h"

namespace clrt {

WaveSizes wave_sizes(std::uint64_t wavefront, std::uint64_t samples, std::uint64_t shadow_samples) {
  WaveSizes s;
  // A pixel's samples always share a wave, so a queue holds at least one pixel's worth.
  s.capacity = std::max(wavefront, samples);
  s.shade_chunk =
      shadow_samples == 0 ? s.capacity : std::max<std::uint64_t>(1, s.capacity / shadow_samples);
  s.shadow_slots = s.shade_chunk * shadow_samples;
  s.wave_pixels = std::max<std::uint64_t>(1, s.capacity / std::max<std::uint64_t>(1, samples));
  return s;
}

std::vector<WaveSizes::Buffer> WaveSizes::buffers() const {
  return {{"ray queue", sizeof(dev::Ray) * capacity},
          {"next ray queue", sizeof(dev::Ray) * capacity},
          {"hit", sizeof(dev::Hit) * capacity},
          {"ray colour", sizeof(dev::f4) * capacity},
          {"spawned ray slot", sizeof(dev::Ray) * 2 * capacity},
          {"spawned ray flag", sizeof(dev::u32) * 2 * capacity},
          {"shadow ray slot", sizeof(dev::ShadowRay) * shadow_slots},
          {"shadow ray flag", sizeof(dev::u32) * shadow_slots},
          {"shadow ray queue", sizeof(dev::ShadowRay) * shadow_slots},
          {"shadow visibility", sizeof(dev::f4) * shadow_slots},
          {"sample colour", sizeof(dev::f4) * capacity},
          {"pixel", sizeof(dev::f4) * wave_pixels}};
}

}  // namespace clrt
