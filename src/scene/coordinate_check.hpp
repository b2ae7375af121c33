// Coordinates the device can compute with: every coordinate in world space, and every point of
// the scene seen in each object's own space, within limits::kMaxCoordinate.
#pragma once

#include "math/vec3.hpp"
#include "scene/loader_state.hpp"
#include "scene/source_location.hpp"

namespace clrt {

// Throws SceneError at `where` if a coordinate of `p` (in world space) is beyond the limit.
void check_world_point(const Vec3& p, const SourceLocation& where);

// After the whole file: each instance's world-space box, and the scene's box mapped into each
// instance's object space (where the device intersects rays with it; a tiny object in a large
// scene sees huge coordinates there). Throws SceneError at the instance's command.
void check_coordinates(const LoaderState& state);

}  // namespace clrt
