// Host-side 4x4 affine transforms in double precision (row-major, column vectors: p' = M p).
#pragma once

#include "math/vec3.hpp"

namespace clrt {

struct Mat4 {
  double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

  static Mat4 identity() { return {}; }
  static Mat4 translate(const Vec3& t);
  static Mat4 scale(const Vec3& s);
  // Right-handed rotation by `degrees` about `axis` (any non-zero length) through the origin.
  static Mat4 rotate(double degrees, const Vec3& axis);

  Mat4 operator*(const Mat4& o) const;
  Vec3 transform_point(const Vec3& p) const;
  Vec3 transform_vector(const Vec3& v) const;
  Mat4 transposed() const;
  // Inverse of an affine matrix (last row 0 0 0 1); the caller guarantees it is invertible.
  Mat4 inverse() const;
};

}  // namespace clrt
