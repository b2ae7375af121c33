// The scene's camera, materials, lights and constants in the layouts the kernels read.
#pragma once

#include <memory>
#include <vector>

#include "math/stratification_grid.hpp"
#include "geometry/geometry_data.hpp"
#include "render/render_options.hpp"
#include "render/texture_table.hpp"
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
  // The environment's texels and rows (kernels/render/lights/environment.h), after the emitter
  // rows in the device's light table; shared by every device's copy of the frame.
  std::shared_ptr<const std::vector<dev::f4>> environment_table;
  std::shared_ptr<const TextureTable> textures;  // likewise shared
};

// The light records: the scene's lights; in path mode, with glowing surfaces in `geometry`'s
// emitter table, the glow light's; with an environment, its record (which the Whitted modes read
// for escaping rays and do not sample).
FrameData make_frame(const Scene& scene, const GeometryData& geometry, const RenderOptions& options);

// The light table as the device reads it: the frame's light records, then `geometry`'s emitter
// rows when the last record is the glow light's (kernels/render/lights/glow.h reads them right
// after it).
std::vector<unsigned char> light_table_bytes(const FrameData& frame, const GeometryData& geometry);

}  // namespace clrt
