// The scene's camera, materials, lights and constants in the layouts the kernels read.
#pragma once

#include <vector>

#include "math/stratification_grid.hpp"
#include "render/render_options.hpp"
#include "scene/scene.hpp"
#include "shared/scene.h"

namespace clrt {

dev::Camera make_camera(const Scene& scene, const RenderOptions& options);
dev::Camera make_camera(const CameraSpec& camera, const RenderOptions& options);
std::vector<dev::Material> make_materials(const Scene& scene);
// Non-ambient lights in file order; ambient lights go into RenderParams::ambient.
std::vector<dev::Light> make_lights(const Scene& scene);
// The CLRT_MODE_* value of a mode: RenderParams.mode, and the transport model its program is built
// with (-DCLRT_TRANSPORT, src/render/renderer_program.cpp).
dev::u32 device_mode(RenderMode mode);

dev::RenderParams make_params(const Scene& scene, const RenderOptions& options);

// Epsilon of the contract, in world units: the origin offset and the smallest accepted t.
constexpr float kEpsilon = 1e-4f;

}  // namespace clrt

namespace clrt {

// Everything but the geometry that one render uploads.
struct FrameData {
  dev::Camera camera{};
  dev::RenderParams params{};
  std::vector<dev::Material> materials;
  std::vector<dev::Light> lights;
};

inline FrameData make_frame(const Scene& scene, const RenderOptions& options) {
  return {make_camera(scene, options), make_params(scene, options), make_materials(scene),
          make_lights(scene)};
}

}  // namespace clrt
