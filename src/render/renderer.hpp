// Rendering a scene: a Renderer builds the geometry once, and a program, frame and integrator
// per device, then renders any number of regions with them (a frame, the tiles of a farm or of
// an MPI rank, the frames of an animation), dealing each region's rows out among its devices.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "device/device_select.hpp"
#include "geometry/geometry_data.hpp"
#include "image/image.hpp"
#include "render/device_preparation.hpp"
#include "render/pixel_rect.hpp"
#include "render/pixel_store.hpp"
#include "render/progress.hpp"
#include "render/render_options.hpp"
#include "render/render_stats.hpp"
#include "scene/scene.hpp"
#include "shared/scene.h"

namespace clrt {

struct RenderSetup {
  RenderOptions options;
  std::vector<DeviceEntry> devices;  // at least one
  bool profile = false;              // per-kernel device times and rays by kind (--stats)
  bool progress = false;             // a progress bar when stderr is a terminal
};

// The pixels a render covers: the options' region, or the whole image.
PixelRect render_region(const RenderOptions& options);

// Throws UsageError when `setup` cannot be rendered as asked (a region outside the image, a
// depth the integrator cannot trace on a device), before any work.
void check_render_setup(const RenderSetup& setup);

// A render that may stop between rounds of samples and go on later (clrt --resume). In: the
// samples of every pixel of the region taken before (0: none, `sums` empty) and their sums, as
// the rounds leave them; out: the samples taken by the end, and their sums when the render
// stopped early or keeps them.
struct ResumableRender {
  std::uint32_t samples = 0;
  std::vector<dev::f4> sums;
  // Whether a finished render leaves its sums too (to add samples to later); else they are
  // left only when it stops early.
  bool keep_finished_sums = false;
  // Asked after each of this render's rounds (the first is 1) whether to stop there.
  std::function<bool(std::uint32_t rounds_done)> stop;
};

class Renderer {
 public:
  // Builds everything a render needs, naming the phases on `progress`; checks `setup` first
  // (check_render_setup).
  Renderer(const Scene& scene, const RenderSetup& setup, Progress* progress = nullptr);
  // The same with the geometry already built (the caller may then free the scene's meshes,
  // release_mesh_data, before the devices are set up). The renderer keeps `geometry`: a CPU
  // device computes in its tables where they lie.
  Renderer(const Scene& scene, GeometryData geometry, const RenderSetup& setup,
           Progress* progress = nullptr);
  // The same on devices whose contexts and programs are ready (prepare_devices), in the
  // order of setup.devices.
  Renderer(const Scene& scene, GeometryData geometry, const RenderSetup& setup,
           std::vector<PreparedDevice> prepared, Progress* progress = nullptr);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders `region` of the image, as linear floats or, `eight_bit`, quantised as the contract
  // says (for the formats that store 8 bits: a quarter of the memory), in rounds of samples
  // (render/sample_rounds.hpp). The image records its placement in the frame unless it is the
  // whole frame; every pixel has the bits of the same pixel of a full render. `progress`
  // advances by render_work(region) in all and shows the samples per pixel done. `watcher`,
  // when given, is handed every band's pixels as well (after each round but the last their
  // mean so far), as they are stored (clrt --preview); the image is the same with or without it.
  // With `resumable`, the rounds start after its samples, from its sums, and may stop early:
  // the image is then the mean of the samples taken (resumable->samples of them), which has
  // the bits of a render of that many samples when the sampler draws sample k whatever the
  // total (path mode's Sobol samples).
  AnyImage render(const PixelRect& region, bool eight_bit, Progress* progress = nullptr,
                  PixelStore* watcher = nullptr, ResumableRender* resumable = nullptr);
  // The units of work of rendering `region`: a camera sample each.
  std::uint64_t render_work(const PixelRect& region) const;

  // The camera of the renders that follow (an animation's next frame).
  void set_camera(const dev::Camera& camera);

  // Waits for the devices and adds what was rendered so far, the set-up times and the devices
  // to `stats` (not load or write).
  void report(RenderStats& stats);

 private:
  struct Devices;
  const RenderOptions options_;
  std::unique_ptr<Devices> devices_;
  RenderStats setup_stats_;  // BVH and kernel build, reported once
  std::uint64_t rays_in_flight_ = 0;  // every lane's wavefront: what a round should keep busy
  std::uint64_t sample_rounds_ = 0;   // the most rounds a render took since the last report
  double render_seconds_ = 0;
};

// One render of the options' region, in floats, with a progress bar when asked.
FloatImage render(const Scene& scene, const RenderSetup& setup, RenderStats& stats);

}  // namespace clrt
