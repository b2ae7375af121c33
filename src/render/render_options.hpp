// What a render is asked for, after the command line has overridden the scene file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

#include <optional>
#include <string>

#include "render/pixel_rect.hpp"
#include "scene/scene.hpp"

namespace clrt {

// Whitted ray tracing (trace), local shading only (cast), Monte Carlo path tracing (path,
// docs/path-tracing.md).
enum class RenderMode { Trace, Cast, Path };

struct RenderOptions {
  int width = 500, height = 300;
  int samples = 1;  // camera samples per pixel
  int max_depth = 5;
  RenderMode mode = RenderMode::Trace;
  std::uint32_t seed = 0;
  // --max-sample-value (pbrt-v4's maxcomponentvalue): a camera sample whose largest channel
  // exceeds this is scaled down to it before the samples of a pixel are averaged, which removes
  // fireflies at the price of bias. Infinity: no clamp, the unbiased estimate.
  float max_sample_value = std::numeric_limits<float>::infinity();
  // --glossy: the trace mode's reflection rays are drawn from the material's normalised Phong
  // lobe about the mirror direction (distribution ray tracing's blurred reflection); the other
  // modes ignore it.
  bool glossy = false;
  // Rays in flight per queue: device memory grows with it, never with the image size.
  // 0 picks the device class's (src/device/device_profile.cpp).
  std::uint32_t wavefront = 0;
  // The name of a row of integrator_table() (render/integrator.hpp), as --integrator takes it:
  // the wavefront is the product, the others the designs it is measured against.
  std::string integrator = "wavefront";
  // The wavefront shades each pass's hits class by class (misses, local terms only, mirrors and
  // glass: kernels/sort_hits.cl) instead of in queue order. The image keeps its bits.
  bool shade_by_class = false;
  // Work-items per work-group; 0 picks the device class's (src/device/device_profile.cpp).
  std::size_t local_size = 0;
  // Waves in flight per device (each with its own queues); 0 picks the device class's.
  std::uint32_t lanes = 0;
  // The pixels to render (pbrt's pixel bounds); the whole image when empty. Every pixel of a
  // region has the bits of the same pixel of the full render.
  std::optional<PixelRect> region;

  // The scene's own settings, for fields the command line leaves alone.
  static RenderOptions from_scene(const Scene& scene);
};

}  // namespace clrt
