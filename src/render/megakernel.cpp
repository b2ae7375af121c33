#include "render/megakernel.hpp"

#include <algorithm>
#include <string>

#include "device/transfer.hpp"
#include "render/usage_error.hpp"

namespace clrt {
namespace {

// Its waves are the wavefront's (the same pixels per wave); it needs no shadow slots.
WaveSizes megakernel_sizes(const IntegratorConfig& config, const DeviceFrame& frame) {
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
  for (DeviceBuffer& b : WaveResolver::buffers(s.capacity, s.wave_pixels))
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
      wave_rays_(static_cast<std::uint32_t>(megakernel_sizes(config, frame).capacity)),
      resolver_(device, program, wave_rays_, wave_rays_, frame.host.params.max_sample_value),
      launcher_(device, config.local_size, config.profile),
      profiler_(launcher_, program, config.profile, 1,
                wave_rays_ / Profiler::kCountChunk + 1, config.timeline),
      megakernel_(program) {
  check_stack_depth(frame.host.params.max_depth, config.megakernel_depth);
  const WaveSizes s = megakernel_sizes(config, frame);
  CLRT_MEGAKERNEL_BUFFERS(CLRT_BUFFER_ALLOCATE)
}

std::uint32_t MegakernelIntegrator::pixels_per_wave(std::uint32_t samples) const {
  return std::max<std::uint32_t>(1, wave_rays_ / samples);
}

void MegakernelIntegrator::render(const PixelRect& rect, RoundOutput& output, std::uint64_t first) {
  const std::uint64_t total = rect.pixel_count();
  const SampleRound& round = output.round();
  for (std::uint64_t done = 0; done < total;) {
    const auto n = static_cast<std::uint32_t>(
        std::min<std::uint64_t>(pixels_per_wave(round.count), total - done));
    const std::uint32_t samples = n * round.count;
    const WaveArgs wave{rect.x,      rect.y,      rect.width, static_cast<std::uint32_t>(done),
                        round.first, round.count, samples};
    launcher_.launch(megakernel_,
                     {frame_.geometry.args(), frame_.params, frame_.camera, frame_.materials,
                      frame_.lights, wave, resolver_.sample_colour(), ray_counts_},
                     samples, 0);
    profiler_.count_rows(ray_counts_, samples, 0);
    profiler_.commit_wave();
    resolver_.resolve(launcher_, output, n, first + done);
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
  for (const DeviceBuffer& b : megakernel_buffers(megakernel_sizes(config_, frame_))) bytes += b.bytes;
  return bytes;
}

}  // namespace clrt
