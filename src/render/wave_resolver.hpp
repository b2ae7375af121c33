// The end of every wave, for both integrators: the camera samples' colours, their sum or mean
// per pixel (kernels/accumulate.cl, resolve) and the pixels' way back to the host.
#pragma once

#include <vector>

#include "render/device_buffer.hpp"
#include "render/sample_rounds.hpp"
#include "render/launcher.hpp"
#include "render/stage_args.hpp"

namespace clrt {

// X(member, element, length, name) for waves of at most `samples` camera samples and `pixels`
// pixels.
#define CLRT_WAVE_RESOLVER_BUFFERS(X)                   \
  X(sample_colour_, dev::f4, samples, "sample colour") \
  X(pixels_, dev::f4, pixels, "pixel")

class WaveResolver {
 public:
  // Camera samples brighter than max_sample_value are scaled down to it (RenderParams).
  WaveResolver(DeviceContext& device, const compute::program& program, std::uint32_t samples,
               std::uint32_t pixels, float max_sample_value);
  // What the constructor allocates.
  static std::vector<DeviceBuffer> buffers(std::uint64_t samples, std::uint64_t pixels);

  // Colour of camera sample i of the wave; the wavefront adds to it pass by pass.
  const Global<dev::f4>& sample_colour() const { return sample_colour_; }
  void clear(std::uint32_t samples);

  // Resolves the wave's pixels after `output`'s round and hands them to it as pixels
  // [first, first + pixel_count).
  void resolve(Launcher& launcher, RoundOutput& output, std::uint32_t pixel_count,
               std::uint64_t first);

  std::uint64_t bytes() const { return bytes_; }

 private:
  DeviceContext& device_;
  float max_sample_value_;
  CLRT_WAVE_RESOLVER_BUFFERS(CLRT_BUFFER_MEMBER)
  std::uint64_t bytes_ = 0;
  TypedKernel<ResolveArgs> resolve_;
  std::vector<dev::f4> host_pixels_;
};

}  // namespace clrt
