#include "render/orbit.hpp"

#include <cmath>

namespace clrt {

CameraSpec orbit_camera(const CameraSpec& camera, double orbit_degrees, std::uint32_t frame,
                        std::uint32_t frames) {
  const double angle = orbit_degrees * M_PI / 180.0 * static_cast<double>(frame) /
                       static_cast<double>(frames);
  const Vec3 axis = normalize(camera.up);
  const Vec3 v = camera.eye - camera.lookat;
  // Rodrigues' rotation of v about the unit axis.
  const double c = std::cos(angle), s = std::sin(angle);
  const Vec3 turned = v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
  CameraSpec out = camera;
  out.eye = camera.lookat + turned;
  return out;
}

}  // namespace clrt
