// The wavefront integrator on one device: waves of pixels go through generate, then passes of
// intersect, shade, shadow (with compaction on the device) and accumulation until no ray is
// left, then resolve. Its queues (WaveQueues), launches and counts (Profiler) and compaction
// (Compactor) each live in their own object; this one only runs the loop.
#pragma once

#include <vector>

#include "render/compactor.hpp"
#include "render/profiler.hpp"
#include "render/integrator.hpp"
#include "render/wave_queues.hpp"
#include "render/wave_resolver.hpp"

namespace clrt {

const IntegratorEntry& wavefront_integrator();

class WavefrontIntegrator final : public Integrator {
 public:
  WavefrontIntegrator(DeviceContext& device, const compute::program& program,
                      const DeviceFrame& frame, const IntegratorConfig& config);

  void render(const PixelRect& rect, RoundOutput& output, std::uint64_t first) override;
  std::uint32_t pixels_per_wave(std::uint32_t samples) const override;
  void harvest(RenderStats& stats) override;
  std::uint64_t device_bytes() const override;

 private:
  // False when a pass spawned more rays than a queue holds: the caller retries with fewer pixels.
  bool render_wave(const PixelRect& rect, std::uint32_t first, std::uint32_t pixel_count,
                   RoundOutput& output, std::uint64_t stored_at);
  void run_pass(std::uint32_t pass, std::uint32_t count);
  void shade_chunk(std::uint32_t pass, std::uint32_t first, std::uint32_t count);
  void shade_by_class(std::uint32_t pass, std::uint32_t first, std::uint32_t count);
  ShadeInputs shade_inputs() const;
  ShadeOutputs shade_outputs() const;
  // Whether rays spawn rays (trace and path modes).
  bool tracing() const { return frame_.host.params.mode != CLRT_MODE_CAST; }

  DeviceContext& device_;
  const DeviceFrame& frame_;
  WaveQueues queues_;
  std::uint32_t wave_rays_;  // camera rays per wave, halved after an overflow
  WaveResolver resolver_;
  Launcher launcher_;
  Profiler profiler_;
  Compactor compactor_;
  TypedKernel<GenerateArgs> generate_;
  TypedKernel<IntersectArgs> intersect_;
  TypedKernel<ShadeArgs> shade_;
  TypedKernel<ShadeSortedArgs> shade_sorted_;
  TypedKernel<ClassifyHitsArgs> classify_;
  bool shade_by_class_;
  TypedKernel<ShadowArgs> shadow_;
  TypedKernel<GatherShadowsArgs> gather_;
  TypedKernel<AccumulateSamplesArgs> accumulate_;
  RenderStats counted_;  // what the host counts itself: passes, waves, restarts
};

}  // namespace clrt
