#include "render/integrators/wavefront.hpp"

#include <algorithm>
#include <string>
#include <vector>

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
  return WaveLoop::with_resolver(WaveQueues::buffers(s), s);
}

}  // namespace

const IntegratorEntry& wavefront_integrator() {
  static const IntegratorEntry entry{
      "wavefront",
      "one kernel per stage, queues compacted every pass (default)",
      [](DeviceClass) { return std::string(); },
      [](const RenderOptions&, const DeviceProfile&) {},  // any depth: an overflow halves the wave
      wavefront_buffers, make_integrator<WavefrontIntegrator>,
      kernel_binding_mismatches<GenerateArgs, IntersectArgs, ShadeArgs, ShadeSortedArgs,
                                ClassifyHitsArgs, ShadowArgs, GatherShadowsArgs,
                                AccumulateSamplesArgs>};
  return entry;
}

WavefrontIntegrator::WavefrontIntegrator(DeviceContext& device, const compute::program& program,
                                         const DeviceFrame& frame, const IntegratorConfig& config)
    : WaveLoop(device, program, frame, config, wavefront_sizes(config, frame), pass_limit(frame)),
      queues_(device, wavefront_sizes(config, frame)),
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

bool WavefrontIntegrator::trace(const WaveArgs& wave) {
  resolver().clear(wave.sample_count);
  launcher().launch(generate_, {frame().camera, wave, queues_.rays}, wave.sample_count, 0);

  std::vector<PassStats> passes;
  std::uint32_t count = wave.sample_count;
  for (std::uint32_t pass = 0; count > 0; ++pass) {
    passes.push_back({count, 0, count, 0});
    run_pass(pass, count);
    if (tracing())
      compactor_.enqueue(launcher(), queues_.spawn_slots, queues_.spawn_flags,
                         CLRT_CHILD_SLOTS * std::size_t{count}, queues_.next_rays, queues_.capacity(), pass);
    launcher().launch(accumulate_,
                      {queues_.rays, queues_.colour, count, resolver().sample_colour()}, count,
                      pass);
    // The one value that crosses to the host in a pass: whether another pass is needed.
    const std::uint32_t next = tracing() ? compactor_.read_total() : 0;
    if (next > queues_.capacity()) return false;
    queues_.advance();
    count = next;
  }
  std::vector<PassStats>& totals = counted().passes;
  if (totals.size() < passes.size()) totals.resize(passes.size());
  for (std::size_t p = 0; p < passes.size(); ++p) {
    totals[p].rays += passes[p].rays;
    totals[p].max_queue = std::max(totals[p].max_queue, passes[p].max_queue);
  }
  return true;
}

void WavefrontIntegrator::run_pass(std::uint32_t pass, std::uint32_t count) {
  profiler().count_queue(queues_.rays, count, pass);
  launcher().launch(intersect_,
                    {frame().geometry.args(), frame().params, queues_.rays, count, queues_.hits},
                    count, pass);
  for (std::uint32_t first = 0; first < count; first += queues_.shade_chunk())
    shade_chunk(pass, first, std::min(queues_.shade_chunk(), count - first));
}

ShadeInputs WavefrontIntegrator::shade_inputs() const {
  return {frame().params, frame().materials, frame().textures, frame().texels, frame().lights, queues_.rays, queues_.hits};
}

ShadeOutputs WavefrontIntegrator::shade_outputs() const {
  return {queues_.colour, queues_.shadow_slots, queues_.shadow_flags, queues_.spawn_slots,
          queues_.spawn_flags};
}

void WavefrontIntegrator::shade_by_class(std::uint32_t pass, std::uint32_t first,
                                         std::uint32_t count) {
  // One launch flags every class; then one class at a time: compact its indices, shade them.
  // Its count stays on the device.
  launcher().launch(classify_,
                    {frame().materials, queues_.hits, first, count, queues_.class_flag_stride(),
                     queues_.shade_indices, queues_.shade_flags},
                    count, pass);
  for (const Global<cl_uint>& flags : queues_.class_flags) {
    compactor_.enqueue(launcher(), queues_.shade_indices, flags, count, queues_.shade_order, count,
                       pass);
    launcher().launch(
        shade_sorted_,
        {shade_inputs(), first, queues_.shade_order, compactor_.total(), shade_outputs()}, count,
        pass);
  }
}

void WavefrontIntegrator::shade_chunk(std::uint32_t pass, std::uint32_t first,
                                      std::uint32_t count) {
  if (shade_by_class_) {
    shade_by_class(pass, first, count);
  } else {
    launcher().launch(shade_, {shade_inputs(), first, count, shade_outputs()}, count, pass);
  }
  const std::size_t slots = std::size_t{count} * frame().host.params.shadow_samples;
  if (!tracing() || slots == 0) return;
  // The shadow queue's length stays on the device: shadow and gather_shadows are launched over
  // all the slots and read it there, so the host never waits in the middle of a pass.
  compactor_.enqueue(launcher(), queues_.shadow_slots, queues_.shadow_flags, slots,
                     queues_.shadow_queue, slots, pass);
  profiler().count_shadows(compactor_.total(), pass);
  launcher().launch(shadow_,
                    {frame().geometry.args(), frame().params, queues_.shadow_queue,
                     compactor_.total(), queues_.visible},
                    slots, pass);
  launcher().launch(gather_,
                    {queues_.shadow_queue, queues_.visible, compactor_.total(), queues_.colour},
                    slots, pass);
}

}  // namespace clrt
