// Profiling of one lane's render: per-kernel and per-pass device times, and rays by kind.
// Nothing here waits on the device before harvest(): the Launcher keeps launch events, read
// here when a wave ends, and ray counts are added up on the device (kernels/ray_counts.cl), so
// turning --stats on does not change what it measures.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "device/device_context.hpp"
#include "render/busy_timeline.hpp"
#include "render/launcher.hpp"
#include "render/render_stats.hpp"
#include "render/stage_args.hpp"

namespace clrt {

class Profiler {
 public:
  // Reads the times of `launcher`'s launches (timed when `enabled`) and launches its own
  // counting kernels through it. `passes`: the most passes a wave can take (the deepest ray
  // plus one). `timeline` (may be null) collects the kernels' execution intervals.
  Profiler(Launcher& launcher, const compute::program& program, bool enabled,
           std::uint32_t passes, std::uint32_t partial_rows, BusyTimeline* timeline = nullptr);

  // Rays by kind of a queue of `count` rays, into the current wave's pass `pass`.
  void count_queue(const Global<dev::Ray>& rays, std::uint32_t count, std::uint32_t pass);
  // The shadow rays a compaction left counted on the device.
  void count_shadows(const Global<cl_uint>& count, std::uint32_t pass);
  // Per-sample counts an integrator wrote itself: `rows` rows of CLRT_RAY_KINDS.
  void count_rows(const Global<cl_uint>& rows, std::uint32_t row_count, std::uint32_t pass);

  // A wave ends: its counts and times join the render's (commit) or are dropped (it is retried).
  std::size_t wave_mark() const { return launcher_.mark(); }
  void commit_wave();
  void drop_wave(std::size_t mark);

  // Reads the times of the launches so far; the caller has waited for them (a wave ends with a
  // blocking read of its pixels), so this never stalls the device, and events do not pile up.
  void settle();

  // Waits for the device, then adds the times and counts so far to `stats` and clears them.
  void harvest(RenderStats& stats);

  // Rays per work-item of count_ray_kinds.
  static constexpr std::uint32_t kCountChunk = 256;

 private:
  Launcher& launcher_;
  DeviceContext& device_;
  bool enabled_;
  BusyTimeline* timeline_;
  std::uint32_t passes_;
  std::map<std::string, KernelStats> kernels_;  // settled times
  std::vector<double> pass_seconds_;
  Global<cl_uint> partial_;
  Global<cl_ulong> staging_, totals_;
  TypedKernel<CountRayKindsArgs> count_ray_kinds_;
  TypedKernel<FoldRayCountsArgs> fold_ray_counts_;
  TypedKernel<AddRayKindsArgs> add_ray_kinds_;
  TypedKernel<AddShadowRaysArgs> add_shadow_rays_;
  TypedKernel<CommitRayCountsArgs> commit_ray_counts_;
};

}  // namespace clrt
