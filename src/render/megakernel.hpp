// The megakernel integrator on one device: one launch per wave, each work-item a camera sample
// walking its whole ray tree (kernels/megakernel.cl), then the wavefront's own resolve. It keeps
// no queues, so its memory is a colour and a count per camera sample of a wave.
#pragma once

#include "render/integrator.hpp"
#include "render/profiler.hpp"
#include "render/wave_resolver.hpp"

namespace clrt {

// Its own buffers, X(member, element, length in elements of WaveSizes s, name); the resolver's
// come with them.
#define CLRT_MEGAKERNEL_BUFFERS(X) \
  X(ray_counts_, cl_uint, CLRT_RAY_KINDS * s.capacity, "ray count")

const IntegratorEntry& megakernel_integrator();

class MegakernelIntegrator final : public Integrator {
 public:
  MegakernelIntegrator(DeviceContext& device, const compute::program& program,
                       const DeviceFrame& frame, const IntegratorConfig& config);

  void render(const PixelRect& rect, RoundOutput& output, std::uint64_t first) override;
  std::uint32_t pixels_per_wave(std::uint32_t samples) const override;
  void harvest(RenderStats& stats) override;
  std::uint64_t device_bytes() const override;

 private:
  const DeviceFrame& frame_;
  IntegratorConfig config_;
  std::uint32_t wave_rays_;
  WaveResolver resolver_;
  CLRT_MEGAKERNEL_BUFFERS(CLRT_BUFFER_MEMBER)
  Launcher launcher_;
  Profiler profiler_;
  TypedKernel<MegakernelArgs> megakernel_;
  std::uint64_t waves_ = 0;
};

}  // namespace clrt
