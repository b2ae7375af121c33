// v and its parts: from, at, up, angle, hither, resolution, one per line in this order.
#include <cmath>

#include "scene/limits.hpp"
#include "scene/nff_state.hpp"

namespace clrt {
namespace {

constexpr const char* kViewParts[] = {"from", "at", "up", "angle", "hither", "resolution"};
constexpr int kViewPartCount = sizeof kViewParts / sizeof kViewParts[0];

int view_part_index(const std::string& name) {
  for (int i = 0; i < kViewPartCount; ++i)
    if (name == kViewParts[i]) return i;
  return -1;
}

// NFF's angle runs between the centres of the outermost pixel columns; clrt's fov spans the whole
// image width, whose edges lie half a pixel further out on each side.
double fov_from_nff_angle(double angle_degrees, int width) {
  if (width < 2) return angle_degrees;
  const double half_tangent = std::tan(angle_degrees * M_PI / 360.0);
  return 2.0 * std::atan(half_tangent * width / (width - 1)) * 180.0 / M_PI;
}

void view(NffState& s, const CommandArgs& a) {
  a.require_count({0});
  if (s.view_at)
    throw SceneError(a.command_location(),
                     "a second view (v): the first is at line " + std::to_string(s.view_at->line));
  s.view_at = a.command_location();
  s.view_part = 0;
}

void from(NffState& s, const CommandArgs& a) {
  a.require_count({3});
  s.loader.scene.camera.eye = a.vec3(0);
  s.loader.eye_set_at = a.command_location();
}

void at(NffState& s, const CommandArgs& a) {
  a.require_count({3});
  s.loader.scene.camera.lookat = a.vec3(0);
  s.loader.lookat_set_at = a.command_location();
}

void up(NffState& s, const CommandArgs& a) {
  a.require_count({3});
  s.loader.scene.camera.up = a.nonzero_vec3(0, "the up vector");
  s.loader.up_set_at = a.command_location();
}

void angle(NffState& s, const CommandArgs& a) {
  a.require_count({1});
  s.angle_degrees = a.number(0);
  if (s.angle_degrees <= 0 || s.angle_degrees >= 180)
    throw a.error_at(0, "the angle must be > 0 and < 180 degrees, found " + a.word(0).text);
  // clrt's fov is wider than NFF's angle (fov_from_nff_angle), so this bounds it too.
  if (s.angle_degrees < limits::kMinFovDegrees)
    throw a.error_at(0, "the angle " + a.word(0).text + " is too narrow for the device's single "
                        "precision: the narrowest is " + short_number(limits::kMinFovDegrees) +
                        " degrees");
}

// clrt has no near plane (camera rays start at the eye), so hither is read and checked only.
void hither(NffState&, const CommandArgs& a) {
  a.require_count({1});
  if (a.number(0) < 0) throw a.error_at(0, "hither must be >= 0, found " + a.word(0).text);
}

void resolution(NffState& s, const CommandArgs& a) {
  a.require_count({2});
  Scene& scene = s.loader.scene;
  const int side = static_cast<int>(limits::kMaxImageSide);
  scene.width = a.whole_number(0, 1, side, "the image width");
  scene.height = a.whole_number(1, 1, side, "the image height");
  scene.camera.fov_degrees = fov_from_nff_angle(s.angle_degrees, scene.width);
}

}  // namespace

void add_nff_view_entities(NffTable& table) {
  table["v"] = view;
  table["from"] = from;
  table["at"] = at;
  table["up"] = up;
  table["angle"] = angle;
  table["hither"] = hither;
  table["resolution"] = resolution;
}

void advance_view(NffState& s, const CommandArgs& a) {
  const int part = view_part_index(a.name());
  if (s.view_part >= 0 && part != s.view_part)
    throw SceneError(a.command_location(), std::string("the view (v) needs '") +
                                               kViewParts[s.view_part] + "' next, found '" +
                                               a.command_word().text + "'");
  if (s.view_part < 0 && part >= 0)
    throw SceneError(a.command_location(),
                     "'" + a.command_word().text +
                         "' belongs to a view: write it after v, in the order from, at, up, "
                         "angle, hither, resolution");
  if (part >= 0) s.view_part = part + 1 < kViewPartCount ? part + 1 : -1;
}

void finish_view(const NffState& s, const SourceLocation& end) {
  if (!s.view_at)
    throw SceneError({s.loader.scene.path, 1, 1},
                     "the file has no view (v): NFF needs one to place the camera");
  if (s.view_part >= 0)
    throw SceneError(end, std::string("the file ends inside the view (v): '") +
                              kViewParts[s.view_part] + "' is missing");
}

}  // namespace clrt
