#include "host_rays.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include "render/frame_setup.hpp"

namespace clrt::compare {
namespace {

Vec3 vec3_of(const dev::f4& v) { return {v.x, v.y, v.z}; }

// Uniform in [0, 1) from the top 53 bits, the same with every standard library.
double uniform(std::mt19937_64& bits) { return static_cast<double>(bits() >> 11) * 0x1.0p-53; }

}  // namespace

HostRay host_ray(const Vec3& origin, const Vec3& unit_dir, float tmax) {
  return {
      {static_cast<float>(origin.x), static_cast<float>(origin.y), static_cast<float>(origin.z)},
      {static_cast<float>(unit_dir.x), static_cast<float>(unit_dir.y),
       static_cast<float>(unit_dir.z)},
      tmax};
}

CameraRays::CameraRays(const Scene& scene, const RenderOptions& options) {
  // Its rays leave a pinhole: a thin lens's would be other rays, so a scene with one is refused.
  if (scene.camera.lens_radius > 0)
    throw std::runtime_error("the scene's thin lens (`lens`) is not traced here: only pinhole "
                             "cameras are");
  const dev::Camera cam = make_camera(scene, options);
  eye_ = vec3_of(cam.eye);
  corner_ = vec3_of(cam.corner);
  dx_ = vec3_of(cam.pixel_dx);
  dy_ = vec3_of(cam.pixel_dy);
  width_ = cam.width;
  height_ = cam.height;
}

HostRay CameraRays::through(unsigned i, unsigned j) const {
  return host_ray(eye_, normalize(corner_ + dx_ * (i + 0.5) + dy_ * (j + 0.5)), INFINITY);
}

RaySet camera_rays(const Scene& scene) {
  const CameraRays camera(scene, RenderOptions::from_scene(scene));
  RaySet set{"camera", {}};
  set.rays.reserve(static_cast<std::size_t>(camera.width()) * camera.height());
  for (unsigned j = 0; j < camera.height(); ++j)
    for (unsigned i = 0; i < camera.width(); ++i) set.rays.push_back(camera.through(i, j));
  return set;
}

RaySet random_rays(const Bounds& bounds, std::size_t count, unsigned seed) {
  std::mt19937_64 bits(seed);
  RaySet set{"random", {}};
  set.rays.reserve(count);
  const Vec3 size = bounds.hi - bounds.lo;
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 origin{bounds.lo.x + size.x * uniform(bits), bounds.lo.y + size.y * uniform(bits),
                      bounds.lo.z + size.z * uniform(bits)};
    // Uniform on the sphere: z uniform in [-1, 1] (Archimedes), azimuth uniform.
    const double z = 1 - 2 * uniform(bits), azimuth = 2 * M_PI * uniform(bits);
    const double across = std::sqrt(std::max(0.0, 1 - z * z));
    set.rays.push_back(
        host_ray(origin, {across * std::cos(azimuth), across * std::sin(azimuth), z}, INFINITY));
  }
  return set;
}

RaySet shadow_rays(const Scene& scene, const RaySet& rays, const std::vector<dev::Hit>& hits) {
  RaySet set{"shadow", {}};
  const std::vector<dev::Light> lights = make_lights(scene);
  if (lights.empty()) return set;
  const dev::Light& light = lights.front();
  const Vec3 target =
      light.kind == dev::CLRT_LIGHT_AREA
          ? vec3_of(light.position) + (vec3_of(light.edge_u) + vec3_of(light.edge_v)) * 0.5
          : vec3_of(light.position);
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (hits[i].instance == CLRT_NO_HIT) continue;
    const Vec3 o = rays.rays[i].origin_vec(), d = rays.rays[i].dir_vec();
    Vec3 normal = vec3_of(hits[i].geometric_normal);
    if (dot(normal, d) > 0) normal = -normal;
    const Vec3 p = o + d * hits[i].geometric_normal.w + normal * kTmin;
    if (light.kind == dev::CLRT_LIGHT_DIRECTIONAL) {
      set.rays.push_back(host_ray(p, -vec3_of(light.direction), INFINITY));
    } else {
      const Vec3 to_light = target - p;
      set.rays.push_back(host_ray(p, normalize(to_light), static_cast<float>(length(to_light))));
    }
  }
  return set;
}

}  // namespace clrt::compare
