#include "geometry/instance_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/instance_motion.hpp"

namespace clrt {
namespace {

struct Extent {
  Vec3 lo, hi;
  void grow(const Extent& o) {
    lo = min(lo, o.lo);
    hi = max(hi, o.hi);
  }
};

// The disk x^2 + z^2 <= r^2 at height y, under M: the ellipse spanned by r times M's x and z
// columns, whose reach along world axis i is r * sqrt(m_i0^2 + m_i2^2).
Extent disk(const Mat4& m, double y, double r) {
  const Vec3 c = m.transform_point({0, y, 0});
  const Vec3 ex = m.column(0), ez = m.column(2);
  const Vec3 half{r * std::hypot(ex.x, ez.x), r * std::hypot(ex.y, ez.y), r * std::hypot(ex.z, ez.z)};
  return {c - half, c + half};
}

// The unit sphere under M reaches sqrt(m_i0^2 + m_i1^2 + m_i2^2) along world axis i.
Extent sphere(const Mat4& m) {
  const Vec3 c = m.transform_point({0, 0, 0});
  const auto reach = [&](int i) { return length(Vec3{m.m[i][0], m.m[i][1], m.m[i][2]}); };
  const Vec3 half{reach(0), reach(1), reach(2)};
  return {c - half, c + half};
}

Extent cube(const Mat4& m) {
  const double inf = std::numeric_limits<double>::infinity();
  Extent e{{inf, inf, inf}, {-inf, -inf, -inf}};
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p = m.transform_point({corner & 1 ? 1.0 : -1.0, corner & 2 ? 1.0 : -1.0, corner & 4 ? 1.0 : -1.0});
    e.grow({p, p});
  }
  return e;
}

// A cylinder or cone is the convex hull of its two cap disks, so its box is theirs.
Extent frustum(const Mat4& m, double r0, double r1) {
  Extent e = disk(m, -1, r0);
  e.grow(disk(m, 1, r1));
  return e;
}

// The object-space box [lo, hi] of a shape that moves from `start` to `end` while turning, in
// world space. At time t a point p of the object is at T(t) + R(t) S(t) p (instance_motion.hpp),
// within |S(t) p| of T(t); S(t) is linear in t and a norm is convex, so |S(t) p| is at most the
// larger of |S0 p| and |S1 p|, and over the box the largest is at a corner. The object stays
// within that reach of the segment from T0 to T1.
Box swept_box(const Vec3& lo, const Vec3& hi, const Mat4& start, const Mat4& end) {
  const Pose poses[2] = {decompose(start), decompose(end)};
  double reach = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
    for (const Pose& pose : poses) {
      const auto& s = pose.stretch;
      const Vec3 sp{s[0] * p.x + s[1] * p.y + s[2] * p.z, s[3] * p.x + s[4] * p.y + s[5] * p.z,
                    s[6] * p.x + s[7] * p.y + s[8] * p.z};
      reach = std::max(reach, length(sp));
    }
  }
  const Vec3 r{reach, reach, reach};
  return padded_world_box(min(poses[0].translation, poses[1].translation) - r,
                          max(poses[0].translation, poses[1].translation) + r);
}

Box joined(Box a, const Box& b) {
  a.grow(b);
  return a;
}

}  // namespace

Box moving_shape_box(const InstanceSpec& spec, const Mat4& end) {
  if (!motion_rotates(spec.transform, end)) {
    // Without turning, each point moves along a line (T and S are linear in t), so the shape's
    // extent along each axis is largest at one of the two poses.
    InstanceSpec at_end = spec;
    at_end.transform = end;
    return joined(shape_world_box(spec), shape_world_box(at_end));
  }
  const double r = spec.shape == ShapeKind::Cone ? std::max(spec.cone_r0, spec.cone_r1) : 1.0;
  return swept_box({-r, -1, -r}, {r, 1, r}, spec.transform, end);
}

Box moving_box(const BoxSet& boxes, const Mat4& start, const Mat4& end) {
  if (!motion_rotates(start, end)) return joined(transformed_box(boxes, start), transformed_box(boxes, end));
  const double inf = std::numeric_limits<double>::infinity();
  double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
  for (std::size_t i = 0; i < boxes.centre[0].size(); ++i)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], boxes.centre[a][i] - boxes.half[a][i]);
      hi[a] = std::max(hi[a], boxes.centre[a][i] + boxes.half[a][i]);
    }
  if (lo[0] > hi[0]) return Box{};
  return swept_box({lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}, start, end);
}

Box shape_world_box(const InstanceSpec& spec) {
  const Mat4& m = spec.transform;
  Extent e;
  switch (spec.shape) {
    case ShapeKind::Sphere: e = sphere(m); break;
    case ShapeKind::Cube: e = cube(m); break;
    case ShapeKind::Cylinder: e = frustum(m, 1, 1); break;
    case ShapeKind::Cone: e = frustum(m, spec.cone_r0, spec.cone_r1); break;
    case ShapeKind::Plane:
    case ShapeKind::Mesh: throw std::logic_error("shape_world_box: not a bounded canonical shape");
  }
  return padded_world_box(e.lo, e.hi);
}

std::optional<WorldSphere> world_sphere(const InstanceSpec& spec) {
  if (spec.shape != ShapeKind::Sphere) return std::nullopt;
  const Mat4& m = spec.transform;
  // A similarity's columns are orthogonal and of one length, the scale.
  const Vec3 c[3] = {m.column(0), m.column(1), m.column(2)};
  const double scale2 = (dot(c[0], c[0]) + dot(c[1], c[1]) + dot(c[2], c[2])) / 3;
  const double tolerance = 1e-6 * scale2;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      if (std::fabs(dot(c[i], c[j]) - (i == j ? scale2 : 0.0)) > tolerance) return std::nullopt;
  return WorldSphere{m.transform_point({0, 0, 0}), std::sqrt(scale2)};
}

}  // namespace clrt
