// Profiling of one device's render: per-kernel and per-pass device times, and rays by kind.
// Nothing here waits on the device before harvest(): launch events are kept and read then, and
// ray counts are added up on the device (kernels/ray_counts.cl), so turning --stats on does not
// change what it measures. Every launch of an integrator goes through launch(), which records
// the event only when profiling is on.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "device/device_context.hpp"
#include "device/typed_kernel.hpp"
#include "render/busy_timeline.hpp"
#include "render/render_stats.hpp"
#include "render/stage_args.hpp"

namespace clrt {

class Profiler {
 public:
  // `passes`: the most passes a wave can take (the deepest ray plus one).
  // `timeline` (may be null) collects the kernels' execution intervals.
  Profiler(DeviceContext& device, const compute::program& program, bool enabled,
           std::size_t local_size, std::uint32_t passes, std::uint32_t partial_rows,
           BusyTimeline* timeline = nullptr);

  bool enabled() const { return enabled_; }
  std::size_t local_size() const { return local_size_; }

  template <class Args>
  void launch(TypedKernel<Args>& kernel, const Args& args, std::size_t items, std::uint32_t pass) {
    compute::event e = kernel.launch(device_.queue(), args, items, local_size_);
    if (enabled_ && items > 0) timed_.push_back({Args::kName, pass, e});
  }

  // Rays by kind of a queue of `count` rays, into the current wave's pass `pass`.
  void count_queue(const Global<dev::Ray>& rays, std::uint32_t count, std::uint32_t pass);
  // The shadow rays a compaction left counted on the device.
  void count_shadows(const Global<cl_uint>& count, std::uint32_t pass);
  // Per-sample counts written by the megakernel: `rows` rows of CLRT_RAY_KINDS.
  void count_rows(const Global<cl_uint>& rows, std::uint32_t row_count, std::uint32_t pass);

  // A wave ends: its counts and times join the render's (commit) or are dropped (it is retried).
  std::size_t wave_mark() const { return timed_.size(); }
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
  struct Timed {
    const char* kernel;
    std::uint32_t pass;
    compute::event event;
  };

  DeviceContext& device_;
  bool enabled_;
  BusyTimeline* timeline_;
  std::size_t local_size_;
  std::uint32_t passes_;
  std::vector<Timed> timed_;
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
