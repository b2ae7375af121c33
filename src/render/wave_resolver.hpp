// The end of every wave, for both integrators: the camera samples' colours, their mean per pixel
// (kernels/accumulate.cl, resolve) and the pixels' way back to the host.
#pragma once

#include <vector>

#include "render/pixel_store.hpp"
#include "render/profiler.hpp"

namespace clrt {

class WaveResolver {
 public:
  WaveResolver(DeviceContext& device, const compute::program& program, std::uint32_t max_samples,
               std::uint32_t max_pixels);

  // Colour of camera sample i of the wave; the wavefront adds to it pass by pass.
  const Global<dev::f4>& sample_colour() const { return sample_colour_; }
  void clear(std::uint32_t samples);

  // Resolves the wave's pixels and stores them as pixels [first, first + pixel_count).
  void resolve(Profiler& profiler, std::uint32_t samples_per_pixel, std::uint32_t pixel_count,
               PixelStore& store, std::uint64_t first);

  std::uint64_t bytes() const;

 private:
  DeviceContext& device_;
  Global<dev::f4> sample_colour_, pixels_;
  std::uint32_t max_samples_, max_pixels_;
  TypedKernel<ResolveArgs> resolve_;
  std::vector<dev::f4> host_pixels_;
};

}  // namespace clrt
