#include "scene/camera_check.hpp"

#include <initializer_list>
#include <limits>

#include "scene/limits.hpp"

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

// The length of a vector whose squared length underflows, scaled up first.
double length_of_tiny(const Vec3& v) {
  const double scale = 0x1p600;
  return length(v * scale) / scale;
}

}  // namespace

void check_camera(const LoaderState& s) {
  const CameraSpec& c = s.scene.camera;
  const Vec3 forward = c.lookat - c.eye;
  if (forward == Vec3{0, 0, 0})
    fail(s, {&s.eye_set_at, &s.lookat_set_at}, "eye and lookat are the same point");
  // Closer than this, the squared distance underflows and the direction cannot be normalised
  // (nor told from parallel to up).
  if (dot(forward, forward) < std::numeric_limits<double>::min())
    fail(s, {&s.eye_set_at, &s.lookat_set_at},
         "the view direction (lookat - eye) is degenerate: eye and lookat are only " +
             short_number(length_of_tiny(forward)) + " apart");
  // Relative test: the cross product of two parallel vectors is zero up to rounding.
  if (length(cross(forward, c.up)) <= 1e-12 * length(forward) * length(c.up))
    fail(s, {&s.eye_set_at, &s.lookat_set_at, &s.up_set_at},
         "the up vector is parallel to the view direction (lookat - eye)");
}

}  // namespace clrt
