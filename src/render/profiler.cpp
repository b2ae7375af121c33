#include "render/profiler.hpp"

#include "device/transfer.hpp"

namespace clrt {
namespace {

void fill_zero(DeviceContext& device, const Global<cl_ulong>& buffer, std::size_t count) {
  const cl_ulong zero = 0;
  device.queue().enqueue_fill_buffer(buffer.buffer, &zero, sizeof zero, 0, sizeof zero * count);
}

}  // namespace

Profiler::Profiler(Launcher& launcher, const compute::program& program, bool enabled,
                   std::uint32_t passes, std::uint32_t partial_rows, BusyTimeline* timeline)
    : launcher_(launcher),
      device_(launcher.device()),
      enabled_(enabled),
      timeline_(timeline),
      passes_(passes),
      partial_(allocate<cl_uint>(device_, enabled ? std::size_t{partial_rows} * CLRT_RAY_KINDS : 1,
                                 "ray count")),
      staging_(allocate<cl_ulong>(device_, enabled ? std::size_t{passes} * CLRT_RAY_KINDS : 1,
                                  "ray count")),
      totals_(allocate<cl_ulong>(device_, enabled ? std::size_t{passes} * CLRT_RAY_KINDS : 1,
                                 "ray count")),
      count_ray_kinds_(program),
      fold_ray_counts_(program),
      add_ray_kinds_(program),
      add_shadow_rays_(program),
      commit_ray_counts_(program) {}

void Profiler::count_queue(const Global<dev::Ray>& rays, std::uint32_t count, std::uint32_t pass) {
  if (!enabled_ || count == 0) return;
  const std::uint32_t chunks = (count + kCountChunk - 1) / kCountChunk;
  launcher_.launch(count_ray_kinds_, {rays, count, kCountChunk, partial_}, chunks, pass);
  launcher_.launch(add_ray_kinds_, {partial_, chunks, pass, staging_}, 1, pass);
}

void Profiler::count_rows(const Global<cl_uint>& rows, std::uint32_t row_count,
                          std::uint32_t pass) {
  if (!enabled_ || row_count == 0) return;
  const std::uint32_t chunks = (row_count + kCountChunk - 1) / kCountChunk;
  launcher_.launch(fold_ray_counts_, {rows, row_count, kCountChunk, partial_}, chunks, pass);
  launcher_.launch(add_ray_kinds_, {partial_, chunks, pass, staging_}, 1, pass);
}

void Profiler::count_shadows(const Global<cl_uint>& count, std::uint32_t pass) {
  if (!enabled_) return;
  launcher_.launch(add_shadow_rays_, {count, pass, staging_}, 1, pass);
}

void Profiler::commit_wave() {
  if (!enabled_) return;
  const std::uint32_t entries = passes_ * CLRT_RAY_KINDS;
  launcher_.launch(commit_ray_counts_, {entries, staging_, totals_}, entries, 0);
}

void Profiler::drop_wave(std::size_t mark) {
  if (!enabled_) return;
  device_.queue().finish();
  launcher_.forget_since(mark);
  fill_zero(device_, staging_, std::size_t{passes_} * CLRT_RAY_KINDS);
}

void Profiler::settle() {
  for (const TimedLaunch& t : launcher_.take()) {
    const auto start = t.event.get_profiling_info<cl_ulong>(CL_PROFILING_COMMAND_START);
    const auto end = t.event.get_profiling_info<cl_ulong>(CL_PROFILING_COMMAND_END);
    if (timeline_) timeline_->add(start, end, t.kernel);
    const double seconds = static_cast<double>(end - start) * 1e-9;
    KernelStats& k = kernels_[t.kernel];
    ++k.launches;
    k.device_seconds += seconds;
    if (pass_seconds_.size() <= t.pass) pass_seconds_.resize(t.pass + 1);
    pass_seconds_[t.pass] += seconds;
  }
}

void Profiler::harvest(RenderStats& stats) {
  device_.queue().finish();
  if (!enabled_) return;
  settle();
  std::vector<cl_ulong> totals(std::size_t{passes_} * CLRT_RAY_KINDS);
  device_.queue().enqueue_read_buffer(totals_.buffer, 0, sizeof(cl_ulong) * totals.size(),
                                      totals.data());
  fill_zero(device_, totals_, totals.size());
  for (std::uint32_t p = 0; p < passes_; ++p)
    for (unsigned k = 0; k < CLRT_RAY_KINDS; ++k) stats.rays[k] += totals[p * CLRT_RAY_KINDS + k];
  for (std::size_t p = 0; p < stats.passes.size() && p < passes_; ++p)
    stats.passes[p].shadow_rays += totals[p * CLRT_RAY_KINDS + CLRT_RAY_SHADOW];
  for (const auto& [name, k] : kernels_) {
    stats.kernels[name].launches += k.launches;
    stats.kernels[name].device_seconds += k.device_seconds;
  }
  for (std::size_t p = 0; p < stats.passes.size() && p < pass_seconds_.size(); ++p)
    stats.passes[p].device_seconds += pass_seconds_[p];
  kernels_.clear();
  pass_seconds_.clear();
}

}  // namespace clrt
