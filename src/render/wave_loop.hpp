// What every integrator does around its own kernels: a band of pixels cut into waves, a wave
// that spawned more rays than a queue holds retried with half the pixels, and the end of each
// wave (its counts and times kept, its pixels resolved and handed over). An integrator derives
// from WaveLoop and traces one wave's camera samples.
#pragma once

#include <cstdint>
#include <vector>

#include "render/integrator.hpp"
#include "render/launcher.hpp"
#include "render/profiler.hpp"
#include "render/wave_resolver.hpp"

namespace clrt {

class WaveLoop : public Integrator {
 public:
  void render(const PixelRect& rect, RoundOutput& output, std::uint64_t first) final;
  std::uint32_t pixels_per_wave(std::uint32_t samples) const final;
  void harvest(RenderStats& stats) final;
  std::uint64_t device_bytes() const final;

  // `own` and the resolver's buffers for waves of `sizes`: what one lane allocates.
  static std::vector<DeviceBuffer> with_resolver(std::vector<DeviceBuffer> own,
                                                 const WaveSizes& sizes);

 protected:
  // Waves of at most `sizes.capacity` camera samples, whose rays take at most `passes` passes.
  WaveLoop(DeviceContext& device, const compute::program& program, const DeviceFrame& frame,
           const IntegratorConfig& config, const WaveSizes& sizes, std::uint32_t passes);

  // Traces `wave`'s camera samples into resolver().sample_colour(). False when they spawned
  // more rays than a queue holds: the wave's launches are then forgotten and it is retried.
  virtual bool trace(const WaveArgs& wave) = 0;
  // The bytes of the integrator's own buffers.
  virtual std::uint64_t own_bytes() const = 0;

  const DeviceFrame& frame() const { return frame_; }
  std::uint32_t capacity() const { return capacity_; }
  Launcher& launcher() { return launcher_; }
  Profiler& profiler() { return profiler_; }
  WaveResolver& resolver() { return resolver_; }
  // What the host counts itself (passes, waves, restarts), added to the harvest.
  RenderStats& counted() { return counted_; }

 private:
  const DeviceFrame& frame_;
  std::uint32_t capacity_;
  std::uint32_t wave_rays_;  // camera samples per wave, halved after an overflow
  WaveResolver resolver_;
  Launcher launcher_;
  Profiler profiler_;
  RenderStats counted_;
};

}  // namespace clrt
