#include "reference_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace clrt::test {
namespace {

constexpr double kEpsilon = 1e-4;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

Vec3 mul(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

// The smallest root t > tmin of |o + t d - c|^2 = r^2.
double sphere_t(const RefSphere& s, const Vec3& o, const Vec3& d, double tmin) {
  const Vec3 oc = o - s.centre;
  const double a = dot(d, d), b = dot(oc, d), c = dot(oc, oc) - s.radius * s.radius;
  const double disc = b * b - a * c;
  if (disc < 0) return kInfinity;
  const double root = std::sqrt(disc);
  for (double t : {(-b - root) / a, (-b + root) / a})
    if (t > tmin) return t;
  return kInfinity;
}

double plane_t(const RefPlane& p, const Vec3& o, const Vec3& d, double tmin) {
  if (d.y == 0) return kInfinity;
  const double t = (p.height - o.y) / d.y;
  return t > tmin ? t : kInfinity;
}

struct LightRay {
  Vec3 l;           // unit, towards the light
  double distance;  // infinite for a directional light
};

LightRay towards(const RefLight& light, const Vec3& p) {
  if (light.directional) return {normalize(-light.travel), kInfinity};
  const Vec3 delta = light.position - p;
  return {normalize(delta), length(delta)};
}

// A hit with epsilon <= t < distance from `origin` along unit `l`.
bool blocked(const RefScene& scene, const Vec3& origin, const LightRay& ray) {
  const RefHit hit = closest_hit(scene, origin, ray.l);
  return hit.object >= 0 && hit.t < ray.distance;
}

struct Surface {
  Vec3 p, n;  // n unit, facing the incoming ray
};

Surface surface_of(const RefHit& hit, const Vec3& origin, const Vec3& dir) {
  const Vec3 n = dot(hit.normal, dir) > 0 ? -hit.normal : hit.normal;
  return {origin + dir * hit.t, n};
}

}  // namespace

RefHit closest_hit(const RefScene& scene, const Vec3& origin, const Vec3& dir) {
  RefHit best;
  best.t = kInfinity;
  int object = 0;
  for (const RefSphere& s : scene.spheres) {
    const double t = sphere_t(s, origin, dir, kEpsilon);
    if (t < best.t) best = {t, normalize(origin + dir * t - s.centre), s.material, object};
    ++object;
  }
  for (const RefPlane& p : scene.planes) {
    const double t = plane_t(p, origin, dir, kEpsilon);
    if (t < best.t) best = {t, {0, 1, 0}, p.material, object};
    ++object;
  }
  return best;
}

Vec3 radiance(const RefScene& scene, const Vec3& origin, const Vec3& dir, int depth, RefMode mode) {
  const RefHit hit = closest_hit(scene, origin, dir);
  if (hit.object < 0) return scene.background;
  const Surface s = surface_of(hit, origin, dir);
  const RefMaterial& m = scene.materials[static_cast<std::size_t>(hit.material)];
  const Vec3 v = -dir;
  Vec3 local = mul(scene.ambient, m.color) * m.ka;
  for (const RefLight& light : scene.lights) {
    const LightRay lr = towards(light, s.p);
    const double nl = dot(s.n, lr.l);
    if (nl <= 0) continue;
    if (mode == RefMode::Trace) {
      const Vec3 from = s.p + s.n * kEpsilon;
      const LightRay shadow = towards(light, from);
      if (blocked(scene, from, shadow)) continue;
    }
    const Vec3 r = s.n * (2 * nl) - lr.l;
    const double highlight = std::pow(std::max(0.0, dot(r, v)), m.shininess);
    local = local + mul(light.color, m.color) * (m.kd * nl) + light.color * (m.ks * highlight);
  }
  Vec3 colour = local * std::max(0.0, 1 - m.kr);
  if (mode == RefMode::Trace && m.kr > 0 && depth < scene.max_depth) {
    const Vec3 reflected = dir - s.n * (2 * dot(dir, s.n));
    colour = colour + radiance(scene, s.p + s.n * kEpsilon, reflected, depth + 1, mode) * m.kr;
  }
  return colour;
}

Vec3 image_colour(const RefScene& scene, double x, double y, RefMode mode) {
  return radiance(scene, scene.camera.eye, scene.camera.direction(x, y), 0, mode);
}

Visibility visibility(const RefScene& scene, double x, double y) {
  const Vec3 dir = scene.camera.direction(x, y);
  const RefHit hit = closest_hit(scene, scene.camera.eye, dir);
  if (hit.object < 0) return Visibility::Background;
  const Surface s = surface_of(hit, scene.camera.eye, dir);
  for (const RefLight& light : scene.lights) {
    if (dot(s.n, towards(light, s.p).l) <= 0) continue;
    const Vec3 from = s.p + s.n * kEpsilon;
    if (blocked(scene, from, towards(light, from))) return Visibility::Shadowed;
  }
  return Visibility::Lit;
}

std::array<int, 3> quantise(const Vec3& colour) {
  const auto q = [](double c) { return static_cast<int>(std::lround(std::clamp(c, 0.0, 1.0) * 255)); };
  return {q(colour.x), q(colour.y), q(colour.z)};
}

bool within_one(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(a[k] - b[k]) > 1) return false;
  return true;
}

bool robust_pixel(const RefScene& scene, int i, int j, RefMode mode) {
  const double cx = i + 0.5, cy = j + 0.5, d = 0.02;
  const auto centre = quantise(image_colour(scene, cx, cy, mode));
  const Visibility seen = visibility(scene, cx, cy);
  const std::pair<double, double> around[4] = {{-d, -d}, {d, -d}, {-d, d}, {d, d}};
  for (const auto& [dx, dy] : around) {
    if (quantise(image_colour(scene, cx + dx, cy + dy, mode)) != centre) return false;
    if (visibility(scene, cx + dx, cy + dy) != seen) return false;
  }
  return true;
}

}  // namespace clrt::test
