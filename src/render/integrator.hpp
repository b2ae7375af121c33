// An integrator renders rectangles of the image on one device. Two exist: the wavefront
// (render/wavefront.hpp), the product, and the megakernel (render/megakernel.hpp), the design it
// is compared with; both give the same bits (kernels/accumulate.cl says why).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "render/busy_timeline.hpp"
#include "render/device_frame.hpp"
#include "render/pixel_rect.hpp"
#include "render/pixel_store.hpp"
#include "render/render_stats.hpp"

namespace clrt {

const char* integrator_name(IntegratorKind kind);
std::optional<IntegratorKind> parse_integrator(const std::string& name);  // any case

struct IntegratorConfig {
  std::uint32_t capacity = 0;      // rays per queue (wavefront), camera samples per launch (both)
  std::size_t local_size = 64;
  std::uint32_t megakernel_depth = 0;  // the megakernel's stack, from the device's program
  bool profile = false;            // per-kernel device times and rays by kind (--stats)
  BusyTimeline* timeline = nullptr;  // the device's, shared by its lanes (profiling only)
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Renders `rect`, its pixels in row-major order, into `store` from its pixel `first` on.
  virtual void render(const PixelRect& rect, PixelStore& store, std::uint64_t first) = 0;
  // Pixels one wave takes: a good size for a piece of work to hand this integrator.
  virtual std::uint32_t pixels_per_wave() const = 0;
  // Waits for the device and adds what was rendered since the last call to `stats`.
  virtual void harvest(RenderStats& stats) = 0;
  // Its own buffers on the device (the frame's are counted once by the caller).
  virtual std::uint64_t device_bytes() const = 0;
};

// Throws UsageError when the megakernel's stack (the device's CLRT_MEGAKERNEL_DEPTH) cannot
// hold a ray tree of `max_depth`: checked before any work.
void check_megakernel_depth(std::uint32_t max_depth, std::uint32_t stack_depth);

std::unique_ptr<Integrator> make_integrator(IntegratorKind kind, DeviceContext& device,
                                            const compute::program& program,
                                            const DeviceFrame& frame,
                                            const IntegratorConfig& config);

}  // namespace clrt
