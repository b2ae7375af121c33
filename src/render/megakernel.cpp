#include "render/megakernel.hpp"

#include <algorithm>

#include "device/transfer.hpp"
#include "render/usage_error.hpp"

namespace clrt {
namespace {

std::uint32_t wave_samples(const IntegratorConfig& config, const DeviceFrame& frame) {
  const std::uint32_t samples = frame.host.camera.samples;
  return std::max(config.capacity, samples) / samples * samples;
}

}  // namespace

MegakernelIntegrator::MegakernelIntegrator(DeviceContext& device, const compute::program& program,
                                           const DeviceFrame& frame,
                                           const IntegratorConfig& config)
    : frame_(frame),
      samples_per_pixel_(frame.host.camera.samples),
      wave_pixels_(wave_samples(config, frame) / frame.host.camera.samples),
      resolver_(device, program, wave_samples(config, frame), wave_pixels_),
      ray_counts_(allocate<cl_uint>(device, std::size_t{wave_samples(config, frame)} * CLRT_RAY_KINDS,
                                    "ray count")),
      profiler_(device, program, config.profile, config.local_size, 1,
                wave_samples(config, frame) / Profiler::kCountChunk + 1, config.timeline),
      megakernel_(program) {
  check_megakernel_depth(frame.host.params.max_depth, config.megakernel_depth);
}

void MegakernelIntegrator::render(const PixelRect& rect, PixelStore& store, std::uint64_t first) {
  const std::uint64_t total = rect.pixel_count();
  for (std::uint64_t done = 0; done < total;) {
    const auto n = static_cast<std::uint32_t>(std::min<std::uint64_t>(wave_pixels_, total - done));
    const std::uint32_t samples = n * samples_per_pixel_;
    const WaveArgs wave{rect.x, rect.y, rect.width, static_cast<std::uint32_t>(done), samples};
    profiler_.launch(megakernel_,
                     {frame_.geometry.args(), frame_.params, frame_.camera, frame_.materials,
                      frame_.lights, wave, resolver_.sample_colour(), ray_counts_},
                     samples, 0);
    profiler_.count_rows(ray_counts_, samples, 0);
    profiler_.commit_wave();
    resolver_.resolve(profiler_, samples_per_pixel_, n, store, first + done);
    profiler_.settle();
    ++waves_;
    done += n;
  }
}

void MegakernelIntegrator::harvest(RenderStats& stats) {
  profiler_.harvest(stats);
  stats.waves += waves_;
  waves_ = 0;
}

std::uint64_t MegakernelIntegrator::device_bytes() const {
  return resolver_.bytes() + std::uint64_t{wave_pixels_} * samples_per_pixel_ * CLRT_RAY_KINDS *
                                 sizeof(cl_uint);
}

}  // namespace clrt
