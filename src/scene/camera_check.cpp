#include "scene/camera_check.hpp"

#include <initializer_list>

namespace clrt {
namespace {

// The latest of the given commands; nullptr if all of them kept their defaults.
const SourceLocation* latest(std::initializer_list<const std::optional<SourceLocation>*> set_at) {
  const SourceLocation* last = nullptr;
  for (const auto* where : set_at)
    if (where->has_value() && (!last || (*where)->line > last->line)) last = &**where;
  return last;
}

[[noreturn]] void fail(const LoaderState& s,
                       std::initializer_list<const std::optional<SourceLocation>*> set_at,
                       const std::string& message) {
  const SourceLocation* where = latest(set_at);
  throw SceneError(where ? *where : SourceLocation{s.scene.path, 1, 1}, message);
}

}  // namespace

void check_camera(const LoaderState& s) {
  const CameraSpec& c = s.scene.camera;
  const Vec3 forward = c.lookat - c.eye;
  if (forward == Vec3{0, 0, 0})
    fail(s, {&s.eye_set_at, &s.lookat_set_at}, "eye and lookat are the same point");
  // Relative test: the cross product of two parallel vectors is zero up to rounding.
  if (length(cross(forward, c.up)) <= 1e-12 * length(forward) * length(c.up))
    fail(s, {&s.eye_set_at, &s.lookat_set_at, &s.up_set_at},
         "the up vector is parallel to the view direction (lookat - eye)");
}

}  // namespace clrt
