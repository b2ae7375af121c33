// An integrator renders rectangles of the image on one device. Each is one host file (its class
// and its IntegratorEntry) and one device file, listed once in integrator_table(): the command
// line, the checks before a render, the experiment runner and the renderer all read that table.
// Two exist: the wavefront (render/wavefront.hpp), the product, and the megakernel
// (render/megakernel.hpp), the design it is compared with; both give the same bits
// (kernels/accumulate.cl says why).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "device/device_tuning.hpp"
#include "render/busy_timeline.hpp"
#include "render/device_buffer.hpp"
#include "render/device_frame.hpp"
#include "render/integrator_names.hpp"
#include "render/pixel_rect.hpp"
#include "render/render_options.hpp"
#include "render/render_stats.hpp"
#include "render/sample_rounds.hpp"
#include "render/wave_sizes.hpp"

namespace clrt {

struct IntegratorConfig {
  std::uint32_t capacity = 0;      // rays per queue (wavefront), camera samples per launch (both)
  std::size_t local_size = 64;
  std::uint32_t megakernel_depth = 0;  // the megakernel's stack, from the device's program
  bool profile = false;            // per-kernel device times and rays by kind (--stats)
  bool shade_by_class = false;     // RenderOptions::shade_by_class
  BusyTimeline* timeline = nullptr;  // the device's, shared by its lanes (profiling only)
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Renders `output`'s round of samples of `rect`, its pixels in row-major order, into
  // `output` from its pixel `first` on.
  virtual void render(const PixelRect& rect, RoundOutput& output, std::uint64_t first) = 0;
  // Pixels one wave takes with `samples` samples each: a good size for a piece of work.
  virtual std::uint32_t pixels_per_wave(std::uint32_t samples) const = 0;
  // Waits for the device and adds what was rendered since the last call to `stats`.
  virtual void harvest(RenderStats& stats) = 0;
  // Its own buffers on the device (the frame's are counted once by the caller).
  virtual std::uint64_t device_bytes() const = 0;
};

struct IntegratorEntry {
  IntegratorKind kind;
  const char* name;     // as --integrator takes it
  const char* summary;  // one line for --help
  // Throws UsageError when a render of `options` cannot run with it on a device tuned as
  // `tuning`: called before any work.
  void (*check)(const RenderOptions& options, const DeviceTuning& tuning);
  // The buffers one lane of it allocates for waves of `sizes`, each as the allocation names it:
  // the checks before a render hold these against the device's limits.
  std::vector<DeviceBuffer> (*buffers)(const WaveSizes& sizes);
  std::unique_ptr<Integrator> (*make)(DeviceContext& device, const compute::program& program,
                                      const DeviceFrame& frame, const IntegratorConfig& config);
};

// Every integrator, the product first.
const std::vector<IntegratorEntry>& integrator_table();
const IntegratorEntry& integrator_entry(IntegratorKind kind);

}  // namespace clrt
