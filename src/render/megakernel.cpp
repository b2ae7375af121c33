#include "render/megakernel.hpp"

#include <algorithm>
#include <string>

#include "device/transfer.hpp"
#include "render/usage_error.hpp"

namespace clrt {
namespace {

// Its waves are the wavefront's (the same pixels per wave); it needs no shadow slots.
WaveSizes sizes_of(const IntegratorConfig& config, const DeviceFrame& frame) {
  return wave_sizes(config.capacity, frame.host.camera.samples, 0);
}

void check_stack_depth(std::uint32_t max_depth, std::uint32_t stack_depth) {
  if (max_depth > stack_depth)
    throw UsageError("the megakernel's ray stack holds trees of depth " +
                     std::to_string(stack_depth) + " on this device, the maximum depth is " +
                     std::to_string(max_depth) +
                     ": lower --max-depth or use --integrator wavefront");
}

std::vector<DeviceBuffer> megakernel_buffers(const WaveSizes& s) {
  std::vector<DeviceBuffer> list{CLRT_MEGAKERNEL_BUFFERS(CLRT_BUFFER_DESCRIBE)};
  for (DeviceBuffer& b : WaveResolver::buffers(s.wave_samples, s.wave_pixels))
    list.push_back(std::move(b));
  return list;
}

}  // namespace

const IntegratorEntry& megakernel_integrator() {
  static const IntegratorEntry entry{
      IntegratorKind::Megakernel, "megakernel",
      "one kernel walks each camera sample's whole ray tree (the design compared with)",
      [](const RenderOptions& options, const DeviceTuning& tuning) {
        check_stack_depth(static_cast<std::uint32_t>(options.max_depth), tuning.megakernel_depth);
      },
      megakernel_buffers,
      [](DeviceContext& device, const compute::program& program, const DeviceFrame& frame,
         const IntegratorConfig& config) -> std::unique_ptr<Integrator> {
        return std::make_unique<MegakernelIntegrator>(device, program, frame, config);
      }};
  return entry;
}

MegakernelIntegrator::MegakernelIntegrator(DeviceContext& device, const compute::program& program,
                                           const DeviceFrame& frame,
                                           const IntegratorConfig& config)
    : frame_(frame),
      config_(config),
      samples_per_pixel_(frame.host.camera.samples),
      wave_pixels_(static_cast<std::uint32_t>(sizes_of(config, frame).wave_pixels)),
      resolver_(device, program, wave_pixels_ * samples_per_pixel_, wave_pixels_),
      launcher_(device, config.local_size, config.profile),
      profiler_(launcher_, program, config.profile, 1,
                wave_pixels_ * samples_per_pixel_ / Profiler::kCountChunk + 1, config.timeline),
      megakernel_(program) {
  check_stack_depth(frame.host.params.max_depth, config.megakernel_depth);
  const WaveSizes s = sizes_of(config, frame);
  CLRT_MEGAKERNEL_BUFFERS(CLRT_BUFFER_ALLOCATE)
}

void MegakernelIntegrator::render(const PixelRect& rect, PixelStore& store, std::uint64_t first) {
  const std::uint64_t total = rect.pixel_count();
  for (std::uint64_t done = 0; done < total;) {
    const auto n = static_cast<std::uint32_t>(std::min<std::uint64_t>(wave_pixels_, total - done));
    const std::uint32_t samples = n * samples_per_pixel_;
    const WaveArgs wave{rect.x, rect.y, rect.width, static_cast<std::uint32_t>(done), samples};
    launcher_.launch(megakernel_,
                     {frame_.geometry.args(), frame_.params, frame_.camera, frame_.materials,
                      frame_.lights, wave, resolver_.sample_colour(), ray_counts_},
                     samples, 0);
    profiler_.count_rows(ray_counts_, samples, 0);
    profiler_.commit_wave();
    resolver_.resolve(launcher_, samples_per_pixel_, n, store, first + done);
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
  std::uint64_t bytes = 0;
  for (const DeviceBuffer& b : megakernel_buffers(sizes_of(config_, frame_))) bytes += b.bytes;
  return bytes;
}

}  // namespace clrt
