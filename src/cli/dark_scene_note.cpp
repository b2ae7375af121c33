#include "cli/dark_scene_note.hpp"

#include <algorithm>

#include "scene/light_kinds.hpp"

namespace clrt {

std::optional<std::string> dark_scene_note(const Scene& scene, RenderMode mode) {
  const Vec3& sky = scene.background;
  const bool dim = std::max({sky.x, sky.y, sky.z}) <= kDimBackground;
  // Glowing surfaces light a path-mode scene; in the Whitted modes they show but light nothing.
  const bool glows = std::any_of(scene.materials.begin(), scene.materials.end(), [](const MaterialSpec& m) {
    return m.emission.x > 0 || m.emission.y > 0 || m.emission.z > 0;
  });
  if ((glows || scene.environment) && mode == RenderMode::Path) return std::nullopt;
  if (glows && scene.lights.empty())
    return std::string("the scene has no light, so only its glowing surfaces show; they light the "
                       "other objects in --mode path (docs/scene-format.md#materials)");
  if (scene.lights.empty() && !scene.instances.empty() && (mode != RenderMode::Path || dim))
    return std::string("the scene has no light, so its objects render black") +
           (mode == RenderMode::Path ? " under its dim background" : "") +
           " (add a `light` line: docs/scene-format.md#lights)";
  if (mode != RenderMode::Path) return std::nullopt;
  bool ambient = false, falls_off = false;
  for (const LightSpec& light : scene.lights) {
    switch (light_kind(light.kind).path_reading) {
      case PathReading::Unused: ambient = true; break;
      case PathReading::FallsOff: falls_off = true; break;
      case PathReading::LikeWhitted: return std::nullopt;
    }
  }
  if (!(ambient || falls_off) || !dim) return std::nullopt;
  std::string why = "in path mode ";
  if (ambient) why += "ambient light is not used";
  if (ambient && falls_off) why += " and ";
  if (falls_off) why += "point and spot lights fall off with distance (1/d^2)";
  const bool black = sky.x == 0 && sky.y == 0 && sky.z == 0;
  return why + "; with no area or directional light and a " + (black ? "black" : "dim") +
         " background the image may be dark (raise --exposure, or see "
         "docs/path-tracing.md#units)";
}

}  // namespace clrt
