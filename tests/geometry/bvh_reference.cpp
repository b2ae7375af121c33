#include "bvh_reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace clrt::bvhtest {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kGrow = 1e-5;

// The smallest of the candidates inside (tmin, tmax), or infinity.
double first_in(std::initializer_list<double> ts, double tmin, double tmax) {
  double best = kInf;
  for (double t : ts)
    if (t > tmin && t < tmax && t < best) best = t;
  return best;
}

// Both roots of a t^2 + 2 b t + c = 0, or NaNs when there is none.
std::array<double, 2> roots(double a, double b, double c) {
  const double disc = b * b - a * c;
  if (a == 0 || disc < 0) return {NAN, NAN};
  const double s = std::sqrt(disc);
  return {(-b - s) / a, (-b + s) / a};
}

double sphere_t(const Vec3& o, const Vec3& d, double tmin, double tmax) {
  const auto r = roots(dot(d, d), dot(o, d), dot(o, o) - 1);
  return first_in({r[0], r[1]}, tmin, tmax);
}

double cube_t(const Vec3& o, const Vec3& d, double tmin, double tmax) {
  double near = -kInf, far = kInf;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0) {
      if (std::fabs(o[a]) > 1) return kInf;
      continue;
    }
    const double t0 = (-1 - o[a]) / d[a], t1 = (1 - o[a]) / d[a];
    near = std::max(near, std::min(t0, t1));
    far = std::min(far, std::max(t0, t1));
  }
  return near <= far ? first_in({near, far}, tmin, tmax) : kInf;
}

// Radius r0 at y = -1 to r1 at y = 1: side hits within the caps' heights, cap hits within
// their discs.
double frustum_t(double r0, double r1, const Vec3& o, const Vec3& d, double tmin, double tmax) {
  const double m = 0.5 * (r1 - r0), k = 0.5 * (r0 + r1);
  const double ro = m * o.y + k;
  const auto side = roots(d.x * d.x + d.z * d.z - m * m * d.y * d.y,
                          o.x * d.x + o.z * d.z - m * d.y * ro, o.x * o.x + o.z * o.z - ro * ro);
  double best = kInf;
  for (double t : side) {
    const Vec3 p = o + t * d;
    if (std::isfinite(t) && std::fabs(p.y) <= 1 && m * p.y + k >= 0)
      best = std::min(best, first_in({t}, tmin, tmax));
  }
  if (d.y != 0) {
    for (double y : {-1.0, 1.0}) {
      const double t = (y - o.y) / d.y, radius = y < 0 ? r0 : r1;
      const Vec3 p = o + t * d;
      if (p.x * p.x + p.z * p.z <= radius * radius) best = std::min(best, first_in({t}, tmin, tmax));
    }
  }
  return best;
}

double canonical_t(const InstanceSpec& s, const Vec3& o, const Vec3& d, double tmin, double tmax) {
  switch (s.shape) {
    case ShapeKind::Sphere: return sphere_t(o, d, tmin, tmax);
    case ShapeKind::Cube: return cube_t(o, d, tmin, tmax);
    case ShapeKind::Cylinder: return frustum_t(1, 1, o, d, tmin, tmax);
    case ShapeKind::Cone: return frustum_t(s.cone_r0, s.cone_r1, o, d, tmin, tmax);
    case ShapeKind::Plane: return d.y == 0 ? kInf : first_in({-o.y / d.y}, tmin, tmax);
    case ShapeKind::Mesh: break;
  }
  return kInf;
}

double triangle_t(const std::array<Vec3, 3>& v, const Vec3& o, const Vec3& d, double tmin,
                  double tmax) {
  const Vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], p = cross(d, e2);
  const double det = dot(e1, p);
  if (det == 0) return kInf;
  const Vec3 s = o - v[0];
  const double u = dot(s, p) / det;
  const Vec3 q = cross(s, e1);
  const double w = dot(d, q) / det;
  if (u < 0 || w < 0 || u + w > 1) return kInf;
  return first_in({dot(e2, q) / det}, tmin, tmax);
}

std::array<Vec3, 3> scaled_about_centre(const std::array<Vec3, 3>& v, double s) {
  const Vec3 c = (v[0] + v[1] + v[2]) / 3.0;
  return {c + (v[0] - c) * s, c + (v[1] - c) * s, c + (v[2] - c) * s};
}

// One object's answers for the object as it is, grown and shrunk.
struct Probe {
  double exact, grown, shrunk;
};

class Search {
 public:
  Search(double tmin, double tmax) : tmin_(tmin), tmax_(tmax) {}

  void add(const ObjectId& id, const Probe& p) {
    const bool stable = std::isfinite(p.grown) == std::isfinite(p.shrunk) &&
                        (!std::isfinite(p.grown) || std::fabs(p.grown - p.shrunk) <= t_tolerance(p.exact));
    if (!stable) unstable_.push_back(std::min({p.exact, p.grown, p.shrunk}));
    if (std::isfinite(p.exact)) hits_.push_back({p.exact, id});
  }

  ReferenceResult result() const {
    ReferenceResult r;
    for (const auto& h : hits_)
      if (h.first > tmin_ && h.first < tmax_ && h.first < r.t) {
        r.t = h.first;
        r.object = h.second;
        r.hit = true;
      }
    const double tol = t_tolerance(r.hit ? r.t : 0);
    for (double t : unstable_) r.ambiguous |= t < r.t + tol;
    for (const auto& h : hits_) {
      r.ambiguous |= !(h.second == r.object) && h.first > tmin_ && h.first < r.t + tol;
      r.ambiguous |= std::fabs(h.first - tmin_) < t_tolerance(tmin_) ||
                     std::fabs(h.first - tmax_) < t_tolerance(tmax_);
    }
    return r;
  }

 private:
  double tmin_, tmax_;
  std::vector<std::pair<double, ObjectId>> hits_;
  std::vector<double> unstable_;
};

}  // namespace

double t_tolerance(double t) { return 1e-3 * (1 + std::fabs(t)); }

ReferenceResult reference_closest_hit(const Scene& scene, const Vec3& o, const Vec3& d,
                                      double tmin_exact, double tmax_exact) {
  Search search(tmin_exact, tmax_exact);
  // Objects are probed over a slightly wider interval, so that hits next to either end are seen
  // and flag the ray.
  const double tmin = tmin_exact - t_tolerance(tmin_exact), tmax = tmax_exact + t_tolerance(tmax_exact);
  const auto add_triangle = [&](const ObjectId& id, const std::array<Vec3, 3>& v) {
    search.add(id, {triangle_t(v, o, d, tmin, tmax),
                    triangle_t(scaled_about_centre(v, 1 + kGrow), o, d, tmin, tmax),
                    triangle_t(scaled_about_centre(v, 1 - kGrow), o, d, tmin, tmax)});
  };
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const InstanceSpec& s = scene.instances[i];
    if (s.shape == ShapeKind::Mesh) {
      const MeshData& mesh = scene.meshes[s.mesh];
      for (std::size_t t = 0; 3 * t < mesh.corners.size(); ++t) {
        std::array<Vec3, 3> v;
        for (int k = 0; k < 3; ++k) v[k] = s.transform.transform_point(mesh.positions[mesh.corners[3 * t + k]]);
        add_triangle({static_cast<int>(i), static_cast<int>(t)}, v);
      }
      continue;
    }
    const Mat4 inverse = s.transform.inverse();
    const Vec3 oo = inverse.transform_point(o), od = inverse.transform_vector(d);
    const auto at_scale = [&](double k) { return canonical_t(s, oo / k, od / k, tmin, tmax); };
    const bool plane = s.shape == ShapeKind::Plane;
    search.add({static_cast<int>(i), -1}, {at_scale(1), plane ? at_scale(1) : at_scale(1 + kGrow),
                                           plane ? at_scale(1) : at_scale(1 - kGrow)});
  }
  for (std::size_t t = 0; t < scene.triangles.size(); ++t) {
    const TriangleSpec& tri = scene.triangles[t];
    add_triangle({-1, static_cast<int>(t)}, {tri.v0, tri.v1, tri.v2});
  }
  return search.result();
}

}  // namespace clrt::bvhtest
