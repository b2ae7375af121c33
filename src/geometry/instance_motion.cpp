#include "geometry/instance_motion.hpp"

#include <algorithm>
#include <cmath>

namespace clrt {
namespace {

using Mat3 = std::array<double, 9>;

Mat3 linear_part(const Mat4& m) {
  Mat3 a{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[3 * r + c] = m.m[r][c];
  return a;
}

double determinant(const Mat3& a) {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
         a[2] * (a[3] * a[7] - a[4] * a[6]);
}

// (a^-1)^T: the cofactor matrix over the determinant.
Mat3 inverse_transposed(const Mat3& a) {
  const double d = determinant(a);
  return {(a[4] * a[8] - a[5] * a[7]) / d, (a[5] * a[6] - a[3] * a[8]) / d, (a[3] * a[7] - a[4] * a[6]) / d,
          (a[2] * a[7] - a[1] * a[8]) / d, (a[0] * a[8] - a[2] * a[6]) / d, (a[1] * a[6] - a[0] * a[7]) / d,
          (a[1] * a[5] - a[2] * a[4]) / d, (a[2] * a[3] - a[0] * a[5]) / d, (a[0] * a[4] - a[1] * a[3]) / d};
}

// R = Q with Q_{k+1} = (Q_k + Q_k^-T) / 2 from Q_0 = A (Higham's iteration, which converges
// quadratically to the orthogonal factor of any invertible A).
Mat3 orthogonal_factor(const Mat3& a) {
  Mat3 q = a;
  for (int k = 0; k < 100; ++k) {
    const Mat3 inv_t = inverse_transposed(q);
    double change = 0;
    for (int i = 0; i < 9; ++i) {
      const double next = 0.5 * (q[i] + inv_t[i]);
      change = std::max(change, std::fabs(next - q[i]));
      q[i] = next;
    }
    if (change < 1e-15) break;
  }
  return q;
}

// The unit quaternion of rotation matrix r (Shepperd's method: from its largest diagonal term).
Quaternion quaternion_of(const Mat3& r) {
  const double trace = r[0] + r[4] + r[8];
  Quaternion q;
  if (trace > 0) {
    const double s = 2 * std::sqrt(1 + trace);
    q = {(r[7] - r[5]) / s, (r[2] - r[6]) / s, (r[3] - r[1]) / s, s / 4};
  } else if (r[0] >= r[4] && r[0] >= r[8]) {
    const double s = 2 * std::sqrt(1 + r[0] - r[4] - r[8]);
    q = {s / 4, (r[1] + r[3]) / s, (r[2] + r[6]) / s, (r[7] - r[5]) / s};
  } else if (r[4] >= r[8]) {
    const double s = 2 * std::sqrt(1 + r[4] - r[0] - r[8]);
    q = {(r[1] + r[3]) / s, s / 4, (r[5] + r[7]) / s, (r[2] - r[6]) / s};
  } else {
    const double s = 2 * std::sqrt(1 + r[8] - r[0] - r[4]);
    q = {(r[2] + r[6]) / s, (r[5] + r[7]) / s, s / 4, (r[3] - r[1]) / s};
  }
  const double n = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return {q.x / n, q.y / n, q.z / n, q.w / n};
}

double dot(const Quaternion& a, const Quaternion& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

bool same(const Quaternion& a, const Quaternion& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w;
}

// The second rotation on the first's side of the quaternion sphere, so the slerp turns the short
// way.
Quaternion facing(const Quaternion& first, const Quaternion& q) {
  return dot(first, q) < 0 ? Quaternion{-q.x, -q.y, -q.z, -q.w} : q;
}

dev::f4 f4_of(double x, double y, double z) {
  return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z), 0.0f};
}

}  // namespace

Pose decompose(const Mat4& m) {
  const Mat3 a = linear_part(m);
  Mat3 q = orthogonal_factor(a);
  const double sign = determinant(q) < 0 ? -1.0 : 1.0;
  for (double& v : q) v *= sign;
  Pose pose;
  pose.translation = {m.m[0][3], m.m[1][3], m.m[2][3]};
  pose.rotation = quaternion_of(q);
  // S = R^T A, made exactly symmetric.
  Mat3 s{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) s[3 * i + j] += q[3 * k + i] * a[3 * k + j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) pose.stretch[3 * i + j] = 0.5 * (s[3 * i + j] + s[3 * j + i]);
  return pose;
}

bool motion_rotates(const Mat4& start, const Mat4& end) {
  const Quaternion a = decompose(start).rotation;
  return !same(a, facing(a, decompose(end).rotation));
}

dev::InstanceMotion device_motion(const Mat4& start, const Mat4& end) {
  const Pose p[2] = {decompose(start), decompose(end)};
  const Quaternion q0 = p[0].rotation, q1 = facing(q0, p[1].rotation);
  dev::InstanceMotion motion{};
  for (int k = 0; k < 2; ++k) {
    const Vec3& t = p[k].translation;
    const std::array<double, 9>& s = p[k].stretch;
    motion.translation[k] = f4_of(t.x, t.y, t.z);
    motion.stretch_diagonal[k] = f4_of(s[0], s[4], s[8]);
    motion.stretch_off[k] = f4_of(s[1], s[2], s[5]);
  }
  const Quaternion q[2] = {q0, q1};
  for (int k = 0; k < 2; ++k)
    motion.rotation[k] = {static_cast<float>(q[k].x), static_cast<float>(q[k].y),
                          static_cast<float>(q[k].z), static_cast<float>(q[k].w)};
  if (!same(q0, q1)) {
    const double angle = std::acos(std::min(1.0, dot(q0, q1)));
    motion.angle_turns = static_cast<float>(angle / (2 * M_PI));
    // A float angle of 0 (rotations a few 1e-8 apart) leaves the device its linear weights.
    if (motion.angle_turns > 0)
      motion.inverse_sine = static_cast<float>(1 / std::sin(2 * M_PI * double{motion.angle_turns}));
  }
  return motion;
}

}  // namespace clrt
