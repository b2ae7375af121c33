#include "render/wavefront.hpp"

#include <algorithm>
#include <string>

namespace clrt {
namespace {

WaveSizes wavefront_sizes(const IntegratorConfig& config, const DeviceFrame& frame) {
  return wave_sizes(config.capacity, frame.host.camera.samples, frame.host.params.shadow_samples);
}

// A path's last ray, drawn at the depth cap, is one level deeper (kernels/render/path_step.h).
std::uint32_t pass_limit(const DeviceFrame& frame) {
  switch (frame.host.params.mode) {
    case CLRT_MODE_CAST: return 1;
    case CLRT_MODE_PATH: return frame.host.params.max_depth + 2;
    default: return frame.host.params.max_depth + 1;
  }
}

std::vector<DeviceBuffer> wavefront_buffers(const WaveSizes& s) {
  std::vector<DeviceBuffer> list = WaveQueues::buffers(s);
  for (DeviceBuffer& b : WaveResolver::buffers(s.capacity, s.wave_pixels)) list.push_back(std::move(b));
  return list;
}

}  // namespace

const IntegratorEntry& wavefront_integrator() {
  static const IntegratorEntry entry{
      IntegratorKind::Wavefront, "wavefront",
      "one kernel per stage, queues compacted every pass (default)",
      [](const RenderOptions&, const DeviceTuning&) {},  // any depth: an overflow halves the wave
      wavefront_buffers,
      [](DeviceContext& device, const compute::program& program, const DeviceFrame& frame,
         const IntegratorConfig& config) -> std::unique_ptr<Integrator> {
        return std::make_unique<WavefrontIntegrator>(device, program, frame, config);
      }};
  return entry;
}

WavefrontIntegrator::WavefrontIntegrator(DeviceContext& device, const compute::program& program,
                                         const DeviceFrame& frame, const IntegratorConfig& config)
    : device_(device),
      frame_(frame),
      queues_(device, wavefront_sizes(config, frame)),
      wave_rays_(queues_.capacity()),
      resolver_(device, program, queues_.capacity(), queues_.capacity(),
                frame.host.params.max_sample_value),
      launcher_(device, config.local_size, config.profile),
      profiler_(launcher_, program, config.profile, pass_limit(frame),
                queues_.capacity() / Profiler::kCountChunk + 1, config.timeline),
      compactor_(device, program,
                 std::max(CLRT_CHILD_SLOTS * std::size_t{queues_.capacity()},
                          queues_.shadow_slots_per_chunk())),
      generate_(program),
      intersect_(program),
      shade_(program),
      shade_sorted_(program),
      classify_(program),
      shade_by_class_(config.shade_by_class),
      shadow_(program),
      gather_(program),
      accumulate_(program) {}

std::uint64_t WavefrontIntegrator::device_bytes() const {
  return queues_.bytes() + resolver_.bytes();
}

std::uint32_t WavefrontIntegrator::pixels_per_wave(std::uint32_t samples) const {
  return std::max<std::uint32_t>(1, wave_rays_ / samples);
}

void WavefrontIntegrator::render(const PixelRect& rect, RoundOutput& output, std::uint64_t first) {
  const std::uint64_t total = rect.pixel_count();
  const std::uint32_t samples = output.round().count;
  std::uint64_t done = 0;
  while (done < total) {
    const auto n = static_cast<std::uint32_t>(
        std::min<std::uint64_t>(pixels_per_wave(samples), total - done));
    if (render_wave(rect, static_cast<std::uint32_t>(done), n, output, first + done)) {
      done += n;
      continue;
    }
    if (n == 1)
      throw DeviceError("the ray tree of one pixel does not fit in a queue of " +
                        std::to_string(queues_.capacity()) +
                        " rays: raise --wavefront or lower the maximum depth");
    wave_rays_ = std::max<std::uint32_t>(1, n / 2) * samples;
    ++counted_.wave_restarts;
  }
}

bool WavefrontIntegrator::render_wave(const PixelRect& rect, std::uint32_t first,
                                      std::uint32_t pixel_count, RoundOutput& output,
                                      std::uint64_t stored_at) {
  const std::size_t mark = profiler_.wave_mark();
  const SampleRound& round = output.round();
  const std::uint32_t samples = pixel_count * round.count;
  resolver_.clear(samples);
  const WaveArgs wave{rect.x, rect.y, rect.width, first, round.first, round.count, samples};
  launcher_.launch(generate_, {frame_.camera, wave, queues_.rays}, samples, 0);

  std::vector<PassStats> passes;
  std::uint32_t count = samples;
  for (std::uint32_t pass = 0; count > 0; ++pass) {
    passes.push_back({count, 0, count, 0});
    run_pass(pass, count);
    if (tracing())
      compactor_.enqueue(launcher_, queues_.spawn_slots, queues_.spawn_flags,
                         CLRT_CHILD_SLOTS * std::size_t{count}, queues_.next_rays, queues_.capacity(), pass);
    launcher_.launch(accumulate_, {queues_.rays, queues_.colour, count, resolver_.sample_colour()},
                     count, pass);
    // The one value that crosses to the host in a pass: whether another pass is needed.
    const std::uint32_t next = tracing() ? compactor_.read_total() : 0;
    if (next > queues_.capacity()) {
      profiler_.drop_wave(mark);
      return false;
    }
    queues_.advance();
    count = next;
  }
  profiler_.commit_wave();
  if (counted_.passes.size() < passes.size()) counted_.passes.resize(passes.size());
  for (std::size_t p = 0; p < passes.size(); ++p) {
    counted_.passes[p].rays += passes[p].rays;
    counted_.passes[p].max_queue = std::max(counted_.passes[p].max_queue, passes[p].max_queue);
  }
  ++counted_.waves;
  resolver_.resolve(launcher_, output, pixel_count, stored_at);
  profiler_.settle();
  return true;
}

void WavefrontIntegrator::run_pass(std::uint32_t pass, std::uint32_t count) {
  profiler_.count_queue(queues_.rays, count, pass);
  launcher_.launch(intersect_,
                   {frame_.geometry.args(), frame_.params, queues_.rays, count, queues_.hits},
                   count, pass);
  for (std::uint32_t first = 0; first < count; first += queues_.shade_chunk())
    shade_chunk(pass, first, std::min(queues_.shade_chunk(), count - first));
}

ShadeInputs WavefrontIntegrator::shade_inputs() const {
  return {frame_.params, frame_.materials, frame_.lights, queues_.rays, queues_.hits};
}

ShadeOutputs WavefrontIntegrator::shade_outputs() const {
  return {queues_.colour, queues_.shadow_slots, queues_.shadow_flags, queues_.spawn_slots,
          queues_.spawn_flags};
}

void WavefrontIntegrator::shade_by_class(std::uint32_t pass, std::uint32_t first,
                                         std::uint32_t count) {
  // One launch flags every class; then one class at a time: compact its indices, shade them.
  // Its count stays on the device.
  launcher_.launch(classify_,
                   {frame_.materials, queues_.hits, first, count, queues_.class_flag_stride(),
                    queues_.shade_indices, queues_.shade_flags},
                   count, pass);
  for (const Global<cl_uint>& flags : queues_.class_flags) {
    compactor_.enqueue(launcher_, queues_.shade_indices, flags, count, queues_.shade_order, count,
                       pass);
    launcher_.launch(shade_sorted_,
                     {shade_inputs(), first, queues_.shade_order, compactor_.total(), shade_outputs()},
                     count, pass);
  }
}

void WavefrontIntegrator::shade_chunk(std::uint32_t pass, std::uint32_t first,
                                      std::uint32_t count) {
  if (shade_by_class_) {
    shade_by_class(pass, first, count);
  } else {
    launcher_.launch(shade_, {shade_inputs(), first, count, shade_outputs()}, count, pass);
  }
  const std::size_t slots = std::size_t{count} * frame_.host.params.shadow_samples;
  if (!tracing() || slots == 0) return;
  // The shadow queue's length stays on the device: shadow and gather_shadows are launched over
  // all the slots and read it there, so the host never waits in the middle of a pass.
  compactor_.enqueue(launcher_, queues_.shadow_slots, queues_.shadow_flags, slots,
                     queues_.shadow_queue, slots, pass);
  profiler_.count_shadows(compactor_.total(), pass);
  launcher_.launch(shadow_,
                   {frame_.geometry.args(), frame_.params, queues_.shadow_queue,
                    compactor_.total(), queues_.visible},
                   slots, pass);
  launcher_.launch(gather_,
                   {queues_.shadow_queue, queues_.visible, compactor_.total(), queues_.colour},
                   slots, pass);
}

void WavefrontIntegrator::harvest(RenderStats& stats) {
  RenderStats own = counted_;
  profiler_.harvest(own);
  counted_ = RenderStats{};
  stats.merge(own);
}

}  // namespace clrt
