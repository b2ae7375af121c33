// The wavefront integrator on one device: waves of pixels go through generate, then passes of
// intersect, shade, shadow (with compaction on the device) and accumulation until no ray is
// left. The waves and their end are WaveLoop's; its queues (WaveQueues) and compaction
// (Compactor) each live in their own object; this one only runs the passes.
#pragma once

#include "render/compactor.hpp"
#include "render/wave_loop.hpp"
#include "render/wave_queues.hpp"

namespace clrt {

class WavefrontIntegrator final : public WaveLoop {
 public:
  WavefrontIntegrator(DeviceContext& device, const compute::program& program,
                      const DeviceFrame& frame, const IntegratorConfig& config);

 private:
  bool trace(const WaveArgs& wave) override;
  std::uint64_t own_bytes() const override { return queues_.bytes(); }
  void run_pass(std::uint32_t pass, std::uint32_t count);
  void shade_chunk(std::uint32_t pass, std::uint32_t first, std::uint32_t count);
  void shade_by_class(std::uint32_t pass, std::uint32_t first, std::uint32_t count);
  ShadeInputs shade_inputs() const;
  ShadeOutputs shade_outputs() const;
  // Whether rays spawn rays (trace and path modes).
  bool tracing() const { return frame().host.params.mode != CLRT_MODE_CAST; }

  WaveQueues queues_;
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
};

}  // namespace clrt
