#include "math/mat4.hpp"

#include <cmath>

namespace clrt {

Mat4 Mat4::translate(const Vec3& t) {
  Mat4 r;
  r.m[0][3] = t.x;
  r.m[1][3] = t.y;
  r.m[2][3] = t.z;
  return r;
}

Mat4 Mat4::scale(const Vec3& s) {
  Mat4 r;
  r.m[0][0] = s.x;
  r.m[1][1] = s.y;
  r.m[2][2] = s.z;
  return r;
}

// Rodrigues' formula: R = cI + s[a]x + (1 - c) a a^T for the unit axis a.
Mat4 Mat4::rotate(double degrees, const Vec3& axis) {
  const Vec3 a = normalize(axis);
  const double rad = degrees * M_PI / 180.0;
  const double c = std::cos(rad), s = std::sin(rad), k = 1.0 - c;
  Mat4 r;
  r.m[0][0] = c + k * a.x * a.x;
  r.m[0][1] = k * a.x * a.y - s * a.z;
  r.m[0][2] = k * a.x * a.z + s * a.y;
  r.m[1][0] = k * a.y * a.x + s * a.z;
  r.m[1][1] = c + k * a.y * a.y;
  r.m[1][2] = k * a.y * a.z - s * a.x;
  r.m[2][0] = k * a.z * a.x - s * a.y;
  r.m[2][1] = k * a.z * a.y + s * a.x;
  r.m[2][2] = c + k * a.z * a.z;
  return r;
}

Mat4 Mat4::operator*(const Mat4& o) const {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += m[i][k] * o.m[k][j];
      r.m[i][j] = sum;
    }
  return r;
}

Vec3 Mat4::transform_point(const Vec3& p) const {
  return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
          m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
          m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
}

Vec3 Mat4::transform_vector(const Vec3& v) const {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
          m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Mat4 Mat4::transposed() const {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
  return r;
}

// The inverse of [A t; 0 1] is [A^-1  -A^-1 t; 0 1]; A^-1 by the adjugate.
Mat4 Mat4::inverse() const {
  const double a = m[0][0], b = m[0][1], c = m[0][2];
  const double d = m[1][0], e = m[1][1], f = m[1][2];
  const double g = m[2][0], h = m[2][1], i = m[2][2];
  const double co00 = e * i - f * h, co01 = f * g - d * i, co02 = d * h - e * g;
  const double inv_det = 1.0 / (a * co00 + b * co01 + c * co02);
  Mat4 r;
  r.m[0][0] = co00 * inv_det;
  r.m[0][1] = (c * h - b * i) * inv_det;
  r.m[0][2] = (b * f - c * e) * inv_det;
  r.m[1][0] = co01 * inv_det;
  r.m[1][1] = (a * i - c * g) * inv_det;
  r.m[1][2] = (c * d - a * f) * inv_det;
  r.m[2][0] = co02 * inv_det;
  r.m[2][1] = (b * g - a * h) * inv_det;
  r.m[2][2] = (a * e - b * d) * inv_det;
  const Vec3 t{m[0][3], m[1][3], m[2][3]};
  const Vec3 it = r.transform_vector(t);
  r.m[0][3] = -it.x;
  r.m[1][3] = -it.y;
  r.m[2][3] = -it.z;
  return r;
}

}  // namespace clrt
