// A whole render: the geometry built once, a program, frame and integrator per device, and the
// image's rows dealt out among the devices.
#pragma once

#include <vector>

#include "device/device_select.hpp"
#include "image/image.hpp"
#include "render/render_options.hpp"
#include "render/render_stats.hpp"
#include "scene/scene.hpp"

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
// megakernel stack too shallow for the depth), before any work.
void check_render_setup(const RenderSetup& setup);

// Renders `scene`; fills the timing, device and ray fields of `stats` (not load or write).
FloatImage render(const Scene& scene, const RenderSetup& setup, RenderStats& stats);

}  // namespace clrt
