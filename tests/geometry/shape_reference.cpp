#include "shape_reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace clrt::test {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

using Vec4 = std::array<double, 4>;

Vec4 times(const Mat4& m, const Vec4& v) {
  Vec4 r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r[i] += m.m[i][j] * v[j];
  return r;
}

double dot4(const Vec4& a, const Vec4& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]; }

Vec3 unit_axis(int i) { return {i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0}; }

// Keeps the nearest hit offered within (tmin, tmax).
class Nearest {
 public:
  explicit Nearest(const WorldRay& ray) : ray_(ray) {}

  void offer(double t, const Vec3& normal, double edge_distance) {
    if (!(t > ray_.tmin && t < ray_.tmax) || (best_.hit && t >= best_.t)) return;
    best_.hit = true;
    best_.t = t;
    best_.normal = normalize(normal);
    best_.edge_distance = edge_distance;
  }

  const ReferenceHit& best() const { return best_; }

 private:
  WorldRay ray_;
  ReferenceHit best_;
};

// The surface p^T Q p = 0 (p homogeneous, Q symmetric, object space) moved to world space as
// H^T Q H with H = M^-1; its outward normal is the world gradient Q_world p. When `slab` is
// set only the part with object-space |y| <= 1 counts.
void add_quadric(const Mat4& q_object, const Mat4& m, bool slab, const WorldRay& ray,
                 Nearest& nearest) {
  const Mat4 h = m.inverse();
  const Mat4 q = h.transposed() * q_object * h;
  const Vec4 o{ray.origin.x, ray.origin.y, ray.origin.z, 1}, d{ray.dir.x, ray.dir.y, ray.dir.z, 0};
  const double a = dot4(d, times(q, d)), b = dot4(d, times(q, o)), c = dot4(o, times(q, o));
  std::vector<double> roots;
  if (a == 0) {
    if (b != 0) roots.push_back(-c / (2 * b));
  } else if (b * b - a * c >= 0) {
    const double s = std::sqrt(b * b - a * c);
    roots = {(-b - s) / a, (-b + s) / a};
  }
  for (const double t : roots) {
    const Vec3 p = ray.origin + t * ray.dir;
    const double y = h.transform_point(p).y;
    if (slab && std::abs(y) > 1) continue;
    const Vec4 g = times(q, {p.x, p.y, p.z, 1});
    nearest.offer(t, {g[0], g[1], g[2]}, slab ? 1 - std::abs(y) : kInfinity);
  }
}

enum class Bound { Square, Disc, None };

// A flat patch of the object: centre + u axis_u + v axis_v with |u|, |v| <= 1 (Square),
// u^2 + v^2 <= radius^2 (Disc) or unbounded; `outward` is its outward side in object space.
struct Patch {
  Vec3 centre, axis_u, axis_v, outward;
  Bound bound = Bound::Square;
  double radius = 1;
};

void add_patch(const Patch& patch, const Mat4& m, const WorldRay& ray, Nearest& nearest) {
  const Vec3 c = m.transform_point(patch.centre);
  const Vec3 eu = m.transform_vector(patch.axis_u), ev = m.transform_vector(patch.axis_v);
  Vec3 n = cross(eu, ev);
  if (dot(n, m.transform_vector(patch.outward)) < 0) n = -n;
  const double along = dot(n, ray.dir);
  if (along == 0) return;
  const double t = dot(n, c - ray.origin) / along;
  const Vec3 r = ray.origin + t * ray.dir - c;
  // r = u eu + v ev, solved by the normal equations (eu and ev need not be orthogonal).
  const double g11 = dot(eu, eu), g12 = dot(eu, ev), g22 = dot(ev, ev);
  const double r1 = dot(eu, r), r2 = dot(ev, r), det = g11 * g22 - g12 * g12;
  const double u = (r1 * g22 - r2 * g12) / det, v = (g11 * r2 - g12 * r1) / det;
  double edge = kInfinity;
  if (patch.bound == Bound::Square) edge = std::min(1 - std::abs(u), 1 - std::abs(v));
  if (patch.bound == Bound::Disc) edge = patch.radius - std::hypot(u, v);
  if (edge >= 0) nearest.offer(t, n, edge);
}

Mat4 diagonal(double a, double b, double c, double d) {
  Mat4 q;
  q.m[0][0] = a;
  q.m[1][1] = b;
  q.m[2][2] = c;
  q.m[3][3] = d;
  return q;
}

// x^2 + z^2 - (m y + k)^2 with R(y) = m y + k the cone's radius (r0 at y = -1, r1 at y = 1).
Mat4 cone_quadric(double r0, double r1) {
  const double m = (r1 - r0) / 2, k = (r0 + r1) / 2;
  Mat4 q = diagonal(1, -m * m, 1, -k * k);
  q.m[1][3] = q.m[3][1] = -m * k;
  return q;
}

void add_caps(double r_bottom, double r_top, const Mat4& m, const WorldRay& ray, Nearest& nearest) {
  const Vec3 x = unit_axis(0), y = unit_axis(1), z = unit_axis(2);
  if (r_bottom > 0) add_patch({-1 * y, x, z, -1 * y, Bound::Disc, r_bottom}, m, ray, nearest);
  if (r_top > 0) add_patch({y, x, z, y, Bound::Disc, r_top}, m, ray, nearest);
}

}  // namespace

ReferenceHit reference_intersect(const PlacedShape& shape, const WorldRay& ray) {
  Nearest nearest(ray);
  const Mat4& m = shape.transform;
  switch (shape.shape) {
    case CLRT_SHAPE_SPHERE:
      add_quadric(diagonal(1, 1, 1, -1), m, false, ray, nearest);
      break;
    case CLRT_SHAPE_PLANE:
      add_patch({{}, unit_axis(2), unit_axis(0), unit_axis(1), Bound::None}, m, ray, nearest);
      break;
    case CLRT_SHAPE_CUBE:
      for (int i = 0; i < 3; ++i)
        for (const double side : {-1.0, 1.0})
          add_patch({side * unit_axis(i), unit_axis((i + 1) % 3), unit_axis((i + 2) % 3),
                     side * unit_axis(i)},
                    m, ray, nearest);
      break;
    case CLRT_SHAPE_CYLINDER:
      add_quadric(diagonal(1, 0, 1, -1), m, true, ray, nearest);
      add_caps(1, 1, m, ray, nearest);
      break;
    case CLRT_SHAPE_CONE:
      add_quadric(cone_quadric(shape.cone_r0, shape.cone_r1), m, true, ray, nearest);
      add_caps(shape.cone_r0, shape.cone_r1, m, ray, nearest);
      break;
    default:
      break;
  }
  return nearest.best();
}

ReferenceHit reference_triangle(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Mat4& m,
                                const WorldRay& ray) {
  const Vec3 w0 = m.transform_point(v0);
  const Vec3 e1 = m.transform_point(v1) - w0, e2 = m.transform_point(v2) - w0;
  const Vec3 n = cross(e1, e2);
  ReferenceHit result;
  const double along = dot(n, ray.dir);
  if (along == 0) return result;
  const double t = dot(n, w0 - ray.origin) / along;
  const Vec3 r = ray.origin + t * ray.dir - w0;
  // r = u e1 + v e2: the sub-triangle areas against the whole one.
  const double u = dot(cross(r, e2), n) / dot(n, n), v = dot(cross(e1, r), n) / dot(n, n);
  const double edge = std::min({u, v, 1 - u - v});
  if (edge < 0 || !(t > ray.tmin && t < ray.tmax)) return result;
  const Vec3 c0{m.m[0][0], m.m[1][0], m.m[2][0]}, c1{m.m[0][1], m.m[1][1], m.m[2][1]};
  const Vec3 c2{m.m[0][2], m.m[1][2], m.m[2][2]};
  const bool mirrors = dot(cross(c0, c1), c2) < 0;
  result = {true, t, normalize(mirrors ? -n : n), edge, u, v};
  return result;
}

}  // namespace clrt::test
