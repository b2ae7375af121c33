#include "render/wave_sizes.hpp"

namespace clrt {

WaveSizes wave_sizes(std::uint64_t wavefront, std::uint64_t samples, std::uint64_t shadow_samples) {
  WaveSizes s;
  // A round of a pixel's samples shares a wave, so a queue holds at least one pixel's worth.
  s.capacity = std::max(wavefront, samples);
  s.shade_chunk =
      shadow_samples == 0 ? s.capacity : std::max<std::uint64_t>(1, s.capacity / shadow_samples);
  s.shadow_slots = s.shade_chunk * shadow_samples;
  s.class_flag_stride =
      (s.shade_chunk + kClassFlagAlignment - 1) / kClassFlagAlignment * kClassFlagAlignment;
  s.wave_pixels = s.capacity;
  return s;
}

}  // namespace clrt
