#include "render/wavefront.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "device/launch.hpp"
#include "shared/ray.h"

namespace clrt {
namespace {

template <class T>
compute::buffer upload(DeviceContext& device, const std::vector<T>& data, const char* what,
                       std::uint64_t& bytes) {
  compute::buffer buffer = device.allocate(sizeof(T) * data.size(), what);
  if (!data.empty())
    device.queue().enqueue_write_buffer(buffer, 0, sizeof(T) * data.size(), data.data());
  bytes += sizeof(T) * data.size();
  return buffer;
}

}  // namespace

std::uint32_t default_wavefront(const compute::device& device) {
  return (device.type() & CL_DEVICE_TYPE_CPU) ? (1u << 14) : (1u << 20);
}

WavefrontRenderer::WavefrontRenderer(DeviceContext& device, const compute::program& program,
                                     const FrameData& frame, const GeometryData& geometry,
                                     std::uint32_t wavefront, bool profile)
    : device_(device),
      frame_(frame),
      // A pixel's samples always share a wave, so a queue holds at least one pixel's worth.
      capacity_(std::max<std::uint32_t>(wavefront, frame.camera.samples)),
      shade_chunk_(frame.params.shadow_samples == 0
                       ? capacity_
                       : std::max<std::uint32_t>(1, capacity_ / frame.params.shadow_samples)),
      wave_pixels_(std::max<std::uint32_t>(1, capacity_ / frame.camera.samples)),
      profile_(profile),
      geometry_(device, geometry),
      camera_(upload(device, std::vector<dev::Camera>{frame.camera}, "camera", stats_.device_bytes)),
      params_(upload(device, std::vector<dev::RenderParams>{frame.params}, "render parameters",
                     stats_.device_bytes)),
      materials_(upload(device, frame.materials, "material", stats_.device_bytes)),
      lights_(upload(device, frame.lights, "light", stats_.device_bytes)),
      rays_(allocate(sizeof(dev::Ray) * capacity_, "ray queue")),
      next_rays_(allocate(sizeof(dev::Ray) * capacity_, "next ray queue")),
      hits_(allocate(sizeof(dev::Hit) * capacity_, "hit")),
      colour_(allocate(sizeof(dev::f4) * capacity_, "ray colour")),
      spawn_slots_(allocate(sizeof(dev::Ray) * 2 * capacity_, "spawned ray slot")),
      spawn_flags_(allocate(sizeof(dev::u32) * 2 * capacity_, "spawned ray flag")),
      shadow_slots_(allocate(sizeof(dev::ShadowRay) * shade_chunk_ * frame.params.shadow_samples,
                             "shadow ray slot")),
      shadow_flags_(allocate(sizeof(dev::u32) * shade_chunk_ * frame.params.shadow_samples,
                             "shadow ray flag")),
      shadow_queue_(allocate(sizeof(dev::ShadowRay) * shade_chunk_ * frame.params.shadow_samples,
                             "shadow ray queue")),
      visible_(allocate(sizeof(dev::f4) * shade_chunk_ * frame.params.shadow_samples,
                        "shadow visibility")),
      sample_colour_(allocate(sizeof(dev::f4) * capacity_, "sample colour")),
      pixels_(allocate(sizeof(dev::f4) * capacity_, "pixel")),
      kind_counts_(allocate(sizeof(dev::u32) * 6, "ray kind counter")),
      generate_(program, "generate"),
      intersect_(program, "intersect"),
      shade_(program, "shade"),
      shadow_(program, "shadow"),
      gather_(program, "gather_shadows"),
      accumulate_(program, "accumulate_samples"),
      resolve_(program, "resolve"),
      count_kinds_(program, "count_kinds"),
      commit_kind_counts_(program, "commit_kind_counts"),
      compactor_(device, program, std::max<std::size_t>(2 * std::size_t{capacity_},
                                                         std::size_t{shade_chunk_} *
                                                             frame.params.shadow_samples)) {
  stats_.device = device.name();
  stats_.wavefront = capacity_;
  stats_.device_bytes += geometry.device_bytes();
  geometry_args_ = geometry_.bind(intersect_, 0);
  geometry_.bind(shadow_, 0);
  clear_kind_counts(0, 6);
  count_kinds_.set_arg(3, kind_counts_);
  commit_kind_counts_.set_arg(0, kind_counts_);
}

void WavefrontRenderer::clear_kind_counts(std::size_t first, std::size_t count) {
  const dev::u32 zero = 0;
  device_.queue().enqueue_fill_buffer(kind_counts_, &zero, sizeof(zero), first * sizeof(zero),
                                      count * sizeof(zero));
}

compute::buffer WavefrontRenderer::allocate(std::size_t bytes, const char* what) {
  stats_.device_bytes += bytes;
  return device_.allocate(bytes, what);
}

void WavefrontRenderer::render(std::uint32_t first_pixel, std::uint32_t pixel_count, float* rgb) {
  std::uint32_t done = 0;
  while (done < pixel_count) {
    const std::uint32_t n = std::min(wave_pixels_, pixel_count - done);
    if (render_wave(first_pixel + done, n, rgb + 3 * std::size_t{done})) {
      done += n;
      continue;
    }
    if (n == 1)
      throw DeviceError("the ray tree of one pixel does not fit in a queue of " +
                        std::to_string(capacity_) +
                        " rays: raise --wavefront or lower the maximum depth");
    wave_pixels_ = std::max<std::uint32_t>(1, n / 2);
    ++stats_.wave_restarts;
  }
  harvest_timings();
}

bool WavefrontRenderer::render_wave(std::uint32_t first_pixel, std::uint32_t pixel_count,
                                    float* rgb) {
  auto& queue = device_.queue();
  const std::size_t timed_mark = timed_.size();
  const std::uint32_t samples = pixel_count * frame_.camera.samples;
  const dev::f4 zero{0, 0, 0, 0};
  queue.enqueue_fill_buffer(sample_colour_, &zero, sizeof(zero), 0, sizeof(zero) * samples);
  generate_.set_args(camera_, first_pixel, samples, rays_);
  trace("generate", 0, generate_, samples);

  RenderStats wave;  // committed only if the wave completes
  std::swap(wave, stats_);
  std::uint32_t count = samples;
  bool overflow = false;
  for (std::size_t pass = 0; count > 0; ++pass) {
    run_pass(pass, count);
    std::uint32_t next = 0;
    if (frame_.params.mode == CLRT_MODE_TRACE) {
      next = compactor_.compact(spawn_slots_, spawn_flags_, 2 * std::size_t{count}, sizeof(dev::Ray),
                                next_rays_, capacity_);
      if (profile_) {
        timed_.push_back({"compact_count", pass, compactor_.count_event()});
        timed_.push_back({"compact_scan", pass, compactor_.scan_event()});
        timed_.push_back({"compact_scatter", pass, compactor_.scatter_event()});
      }
    }
    accumulate_.set_args(rays_, colour_, count, sample_colour_);
    trace("accumulate_samples", pass, accumulate_, count);
    if (next > capacity_) {
      overflow = true;
      break;
    }
    std::swap(rays_, next_rays_);
    count = next;
  }
  std::swap(wave, stats_);
  if (overflow) {
    queue.finish();
    timed_.erase(timed_.begin() + static_cast<std::ptrdiff_t>(timed_mark), timed_.end());
    if (profile_) clear_kind_counts(0, 3);
    return false;
  }
  if (profile_) trace("commit_kind_counts", 0, commit_kind_counts_, 3);
  stats_.merge(wave);
  ++stats_.waves;

  resolve_.set_args(sample_colour_, frame_.camera.samples, pixel_count, pixels_);
  trace("resolve", 0, resolve_, pixel_count);
  std::vector<dev::f4> pixels(pixel_count);
  queue.enqueue_read_buffer(pixels_, 0, sizeof(dev::f4) * pixel_count, pixels.data());
  for (std::uint32_t p = 0; p < pixel_count; ++p) {
    rgb[3 * p + 0] = pixels[p].x;
    rgb[3 * p + 1] = pixels[p].y;
    rgb[3 * p + 2] = pixels[p].z;
  }
  return true;
}

void WavefrontRenderer::run_pass(std::size_t pass, std::uint32_t count) {
  if (stats_.passes.size() <= pass) stats_.passes.resize(pass + 1);
  PassStats& p = stats_.passes[pass];
  p.rays += count;
  p.max_queue = std::max<std::uint64_t>(p.max_queue, count);
  if (profile_) {
    constexpr std::uint32_t kRaysPerItem = 256;
    count_kinds_.set_arg(0, rays_);
    count_kinds_.set_arg(1, count);
    count_kinds_.set_arg(2, kRaysPerItem);
    trace("count_kinds", pass, count_kinds_, (count + kRaysPerItem - 1) / kRaysPerItem);
  }
  intersect_.set_arg(geometry_args_ + 0, params_);
  intersect_.set_arg(geometry_args_ + 1, rays_);
  intersect_.set_arg(geometry_args_ + 2, count);
  intersect_.set_arg(geometry_args_ + 3, hits_);
  trace("intersect", pass, intersect_, count);
  for (std::uint32_t first = 0; first < count; first += shade_chunk_)
    shade_chunk(pass, first, std::min(shade_chunk_, count - first));
}

void WavefrontRenderer::shade_chunk(std::size_t pass, std::uint32_t first, std::uint32_t count) {
  shade_.set_args(params_, materials_, lights_, rays_, hits_, first, count, colour_, shadow_slots_,
                  shadow_flags_, spawn_slots_, spawn_flags_);
  trace("shade", pass, shade_, count);
  const std::size_t slots = std::size_t{count} * frame_.params.shadow_samples;
  if (frame_.params.mode != CLRT_MODE_TRACE || slots == 0) return;
  // The shadow queue's length stays on the device: shadow and gather_shadows are launched over
  // all the slots and read it there, so the host never waits in the middle of a pass.
  compactor_.enqueue(shadow_slots_, shadow_flags_, slots, sizeof(dev::ShadowRay), shadow_queue_,
                     slots);
  if (profile_) {
    timed_.push_back({"compact_count", pass, compactor_.count_event()});
    timed_.push_back({"compact_scan", pass, compactor_.scan_event()});
    timed_.push_back({"compact_scatter", pass, compactor_.scatter_event()});
    const std::uint32_t shadows = compactor_.read_total();
    stats_.shadow_rays += shadows;
    stats_.passes[pass].shadow_rays += shadows;
  }
  shadow_.set_arg(geometry_args_ + 0, params_);
  shadow_.set_arg(geometry_args_ + 1, shadow_queue_);
  shadow_.set_arg(geometry_args_ + 2, compactor_.total());
  shadow_.set_arg(geometry_args_ + 3, visible_);
  trace("shadow", pass, shadow_, slots);
  gather_.set_args(shadow_queue_, visible_, compactor_.total(), colour_);
  trace("gather_shadows", pass, gather_, slots);
}

void WavefrontRenderer::trace(const char* kernel, std::size_t pass, compute::kernel& k,
                              std::size_t items) {
  compute::event e = launch(device_.queue(), k, items);
  if (profile_ && items > 0) timed_.push_back({kernel, pass, e});
}

void WavefrontRenderer::harvest_timings() {
  device_.queue().finish();
  if (profile_) {
    dev::u32 kinds[3];
    device_.queue().enqueue_read_buffer(kind_counts_, 3 * sizeof(dev::u32), sizeof(kinds), kinds);
    clear_kind_counts(3, 3);
    stats_.camera_rays += kinds[CLRT_RAY_CAMERA];
    stats_.reflection_rays += kinds[CLRT_RAY_REFLECTION];
    stats_.refraction_rays += kinds[CLRT_RAY_REFRACTION];
  }
  for (const Timed& t : timed_) {
    const double seconds =
        static_cast<double>(t.event.get_profiling_info<cl_ulong>(CL_PROFILING_COMMAND_END) -
                            t.event.get_profiling_info<cl_ulong>(CL_PROFILING_COMMAND_START)) *
        1e-9;
    KernelStats& k = stats_.kernels[t.kernel];
    ++k.launches;
    k.device_seconds += seconds;
    if (t.pass < stats_.passes.size()) stats_.passes[t.pass].device_seconds += seconds;
  }
  timed_.clear();
}

}  // namespace clrt
