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
  // Column j of the linear part: where the object's unit axis j goes.
  Vec3 column(int j) const { return {m[0][j], m[1][j], m[2][j]}; }
  // The linear part's determinant: negative when M turns space inside out.
  double determinant() const { return dot(column(0), cross(column(1), column(2))); }
  // Inverse of an affine matrix (last row 0 0 0 1); the caller guarantees it is invertible.
  Mat4 inverse() const;
};

}  // namespace clrt
