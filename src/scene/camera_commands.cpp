// eye, lookat, up, fov, lens, shutter, background, resolution, maxdepth, samples.
#include "scene/command_table.hpp"
#include "scene/limits.hpp"

namespace clrt {
namespace {

void eye(LoaderState& s, const CommandArgs& a) {
  a.require_count({3});
  s.scene.camera.eye = a.vec3(0);
  s.eye_set_at = a.command_location();
}

void lookat(LoaderState& s, const CommandArgs& a) {
  a.require_count({3});
  s.scene.camera.lookat = a.vec3(0);
  s.lookat_set_at = a.command_location();
}

void up(LoaderState& s, const CommandArgs& a) {
  a.require_count({3});
  s.scene.camera.up = a.nonzero_vec3(0, "the up vector");
  s.up_set_at = a.command_location();
}

void fov(LoaderState& s, const CommandArgs& a) {
  a.require_count({1});
  const double degrees = a.number(0);
  if (degrees <= 0 || degrees >= 180)
    throw a.error_at(0, "fov must be > 0 and < 180 degrees, found " + excerpt(a.word(0).text));
  if (degrees < limits::kMinFovDegrees)
    throw a.error_at(0, "fov " + excerpt(a.word(0).text) + " is too narrow for the device's single "
                        "precision: the narrowest is " + short_number(limits::kMinFovDegrees) +
                        " degrees");
  s.scene.camera.fov_degrees = degrees;
}

// lens RADIUS FOCUS: pbrt's lensradius and focaldistance.
void lens(LoaderState& s, const CommandArgs& a) {
  a.require_count({2});
  const double radius = a.number(0), focus = a.number(1);
  if (radius < 0)
    throw a.error_at(0, "the lens radius must be >= 0 (0 is a pinhole), found " + excerpt(a.word(0).text));
  if (focus <= 0)
    throw a.error_at(1, "the focus distance must be > 0, found " + excerpt(a.word(1).text));
  s.scene.camera.lens_radius = radius;
  s.scene.camera.focus_distance = focus;
}

// shutter OPEN CLOSE: the times the camera's samples are spread over.
void shutter(LoaderState& s, const CommandArgs& a) {
  a.require_count({2});
  const double open = a.number(0), close = a.number(1);
  if (close < open)
    throw a.error_at(1, "the shutter must close at or after it opens (" + excerpt(a.word(0).text) +
                            "), found " + excerpt(a.word(1).text));
  s.scene.camera.shutter_open = open;
  s.scene.camera.shutter_close = close;
}

void background(LoaderState& s, const CommandArgs& a) {
  a.require_count({3});
  s.scene.background = a.vec3(0);
}

void resolution(LoaderState& s, const CommandArgs& a) {
  a.require_count({2});
  constexpr int kSide = static_cast<int>(limits::kMaxImageSide);
  const int width = a.whole_number(0, 1, kSide, "the image width");
  const int height = a.whole_number(1, 1, kSide, "the image height");
  if (std::int64_t{width} * height > limits::kMaxPixels)
    throw a.error_at(0, "the image would have " + std::to_string(std::int64_t{width} * height) +
                            " pixels, more than the limit of " +
                            std::to_string(limits::kMaxPixels));
  s.scene.width = width;
  s.scene.height = height;
}

void maxdepth(LoaderState& s, const CommandArgs& a) {
  a.require_count({1});
  s.scene.max_depth = a.whole_number(0, 0, static_cast<int>(limits::kMaxDepth), "maxdepth");
}

void samples(LoaderState& s, const CommandArgs& a) {
  a.require_count({1});
  s.scene.samples =
      a.whole_number(0, 1, static_cast<int>(limits::kMaxSamples), "the number of samples");
}

}  // namespace

void add_camera_commands(CommandTable& table) {
  table["eye"] = eye;
  table["lookat"] = lookat;
  table["up"] = up;
  table["fov"] = fov;
  table["lens"] = lens;
  table["shutter"] = shutter;
  table["background"] = background;
  table["resolution"] = resolution;
  table["maxdepth"] = maxdepth;
  table["samples"] = samples;
}

}  // namespace clrt
