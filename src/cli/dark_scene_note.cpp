#include "cli/dark_scene_note.hpp"

#include <algorithm>

namespace clrt {

std::optional<std::string> dark_scene_note(const Scene& scene, RenderMode mode) {
  if (mode != RenderMode::Path) return std::nullopt;
  bool ambient = false, falls_off = false;
  for (const LightSpec& light : scene.lights) {
    switch (light.kind) {
      case LightKind::Ambient: ambient = true; break;
      case LightKind::Point:
      case LightKind::Spot: falls_off = true; break;
      // Both light a path-mode scene as brightly as a Whitted one.
      case LightKind::Area:
      case LightKind::Directional: return std::nullopt;
    }
  }
  const Vec3& sky = scene.background;
  if (!(ambient || falls_off) || std::max({sky.x, sky.y, sky.z}) > kDimBackground)
    return std::nullopt;
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
