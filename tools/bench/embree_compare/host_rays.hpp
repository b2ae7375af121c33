// The ray sets both tracers get: camera rays, incoherent rays, and shadow rays from the
// camera rays' hits towards the first light. Every ray accepts hits with kTmin < t < tmax.
#pragma once

#include <string>
#include <vector>

#include "math/vec3.hpp"
#include "render/render_options.hpp"
#include "scene/scene.hpp"
#include "shared/ray.h"

namespace clrt::compare {

// The contract's epsilon: the smallest accepted t, and the offset of a shadow ray's origin.
constexpr float kTmin = 1e-4f;

struct HostRay {
  float origin[3];
  float dir[3];  // unit
  float tmax;

  Vec3 origin_vec() const { return {origin[0], origin[1], origin[2]}; }
  Vec3 dir_vec() const { return {dir[0], dir[1], dir[2]}; }
};

// The ray from `origin` along `unit_dir`, rounded to single precision.
HostRay host_ray(const Vec3& origin, const Vec3& unit_dir, float tmax);

// The renderer's camera (render/frame_setup.hpp) for the options' size: the ray through the
// centre of pixel (i, j), rows from the top.
class CameraRays {
 public:
  CameraRays(const Scene& scene, const RenderOptions& options);
  unsigned width() const { return width_; }
  unsigned height() const { return height_; }
  HostRay through(unsigned i, unsigned j) const;

 private:
  Vec3 eye_, corner_, dx_, dy_;
  unsigned width_, height_;
};

struct RaySet {
  std::string name;
  std::vector<HostRay> rays;
};

struct Bounds {
  Vec3 lo, hi;
};

// One ray through the centre of every pixel of the scene's camera at its resolution, rows from
// the top, as the renderer's camera (render/frame_setup.hpp) defines them.
RaySet camera_rays(const Scene& scene);

// `count` rays from uniform points of `bounds` in uniform directions; the same for a seed.
RaySet random_rays(const Bounds& bounds, std::size_t count, unsigned seed);

// From each hit of `rays` (offset by kTmin along the normal, to the side the ray came from)
// towards the scene's first non-ambient light, stopping at the light. Empty when the scene has
// no such light.
RaySet shadow_rays(const Scene& scene, const RaySet& rays, const std::vector<dev::Hit>& hits);

}  // namespace clrt::compare
