// A word for a scene whose image will come out black or nearly so: one with objects and no light
// at all, or one lit for the Whitted modes and rendered in path mode, where its lights mean
// something else (docs/path-tracing.md#units).
#pragma once

#include <optional>
#include <string>

#include "render/render_options.hpp"
#include "scene/scene.hpp"

namespace clrt {

// Why the image may be dark, or nothing: for a scene with objects and no light, in the Whitted
// modes (they are black) and in path mode under a dim background; in path mode, for a scene with
// an ambient, point or spot light but no area or directional light and a background no channel
// of which exceeds kDimBackground (the background lights a path-mode scene; a black one lights
// nothing).
std::optional<std::string> dark_scene_note(const Scene& scene, RenderMode mode);

constexpr double kDimBackground = 0.1;

}  // namespace clrt
