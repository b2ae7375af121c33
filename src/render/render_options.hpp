// What a render is asked for, after the command line has overridden the scene file.
#pragma once

#include <cstdint>

#include "scene/scene.hpp"

namespace clrt {

enum class RenderMode { Trace, Cast };

struct RenderOptions {
  int width = 500, height = 300;
  int samples = 1;  // camera samples per pixel
  int max_depth = 5;
  RenderMode mode = RenderMode::Trace;
  std::uint32_t seed = 0;
  // Rays in flight per queue: device memory grows with it, never with the image size.
  // 0 picks default_wavefront() for each device.
  std::uint32_t wavefront = 0;

  // The scene's own settings, for fields the command line leaves alone.
  static RenderOptions from_scene(const Scene& scene);
};

}  // namespace clrt
