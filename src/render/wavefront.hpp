// The wavefront loop on one device: waves of pixels go through generate, then passes of
// intersect, shade, shadow (with compaction) and accumulation until no ray is left, then
// resolve. Device memory is fixed by the wavefront size, whatever the image size or depth.
#pragma once

#include <cstdint>
#include <vector>

#include "device/device_context.hpp"
#include "geometry/device_geometry.hpp"
#include "geometry/geometry_data.hpp"
#include "render/compactor.hpp"
#include "render/frame_setup.hpp"
#include "render/render_stats.hpp"

namespace clrt {

// Rays per queue when the user names none. On PoCL's CPU device 16384 rendered fastest
// (measured from 4096 to 1M: the queues then stay in the caches; README, "Choosing the
// wavefront"); a GPU needs many more rays in flight to fill its cores.
std::uint32_t default_wavefront(const compute::device& device);

class WavefrontRenderer {
 public:
  WavefrontRenderer(DeviceContext& device, const compute::program& program, const FrameData& frame,
                    const GeometryData& geometry, std::uint32_t wavefront, bool profile);

  // Renders pixels [first, first + count) (row-major over the image) into rgb[3 * count].
  void render(std::uint32_t first_pixel, std::uint32_t pixel_count, float* rgb);

  const RenderStats& stats() const { return stats_; }
  // Pixels one wave takes: a good size for a range of pixels to hand this renderer.
  std::uint32_t pixels_per_wave() const { return wave_pixels_; }

 private:
  struct Timed {
    const char* kernel;
    std::size_t pass;
    compute::event event;
  };

  // False when a pass spawned more rays than a queue holds: the caller retries with fewer pixels.
  bool render_wave(std::uint32_t first_pixel, std::uint32_t pixel_count, float* rgb);
  void run_pass(std::size_t pass, std::uint32_t count);
  void shade_chunk(std::size_t pass, std::uint32_t first, std::uint32_t count);
  void trace(const char* kernel, std::size_t pass, compute::kernel& k, std::size_t items);
  // Profiling times and ray-kind counts are read once per render() call, not per pass.
  void harvest_timings();
  void clear_kind_counts(std::size_t first, std::size_t count);
  compute::buffer allocate(std::size_t bytes, const char* what);

  DeviceContext& device_;
  FrameData frame_;
  std::uint32_t capacity_;       // rays per queue
  std::uint32_t shade_chunk_;    // rays shaded per launch: their shadow slots fill the buffers
  std::uint32_t wave_pixels_;    // pixels per wave, halved after an overflow
  bool profile_;
  RenderStats stats_;
  std::vector<Timed> timed_;

  DeviceGeometry geometry_;
  cl_uint geometry_args_ = 0;  // the SCENE_PARAMS come first; the stage's own arguments follow
  compute::buffer camera_, params_, materials_, lights_;
  compute::buffer rays_, next_rays_, hits_, colour_, spawn_slots_, spawn_flags_;
  compute::buffer shadow_slots_, shadow_flags_, shadow_queue_, visible_;
  compute::buffer sample_colour_, pixels_, kind_counts_;
  compute::kernel generate_, intersect_, shade_, shadow_, gather_, accumulate_, resolve_,
      count_kinds_, commit_kind_counts_;
  Compactor compactor_;
};

}  // namespace clrt
