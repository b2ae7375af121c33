// A moving instance's pose on the device (kernels/geometry/motion.h) against the host. Each
// motion is built from known parts, so the pose at time t is known without decomposing or
// slerping: a turn about one axis is the turn by the interpolated angle; a turn between two
// axes is the first rotation followed by the relative rotation's axis turned through t times its
// angle (worked out from the matrices in double); a mirrored pose keeps its mirror; stretches and
// translations interpolate linearly. The device's rows of M(t)^-1 and (M(t)^-1)^T must match
// those of the host's M(t), times outside [0, 1] holding the nearer pose.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "cl_fixture.hpp"
#include "geometry/device_geometry.hpp"
#include "geometry/instance_motion.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

const std::string kKernel = R"CL(
#include "geometry/motion.h"

__kernel void motion_frames(__global const InstanceMotion* motions, __global const float* times,
                            uint time_count, uint count, __global float4* rows) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const InstanceFrame f = motion_frame(motions + i / time_count, times[i % time_count]);
  for (int r = 0; r < 3; ++r) {
    rows[6 * i + r] = f.to_object[r];
    rows[6 * i + 3 + r] = f.normal_to_world[r];
  }
}
)CL";

struct MotionFramesArgs {
  static constexpr const char* kName = "motion_frames";
  Global<const dev::InstanceMotion> motions;
  Global<const float> times;
  cl_uint time_count = 0;
  cl_uint count = 0;
  Global<dev::f4> rows;
  CLRT_KERNEL_ARGS(motions, times, time_count, count, rows)
};

double lerp(double a, double b, double t) { return (1 - t) * a + t * b; }
Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return a * (1 - t) + b * t; }

// The axis and angle (degrees) of rotation matrix r, from its skew part and trace.
void axis_angle(const Mat4& r, Vec3& axis, double& degrees) {
  const Vec3 skew{r.m[2][1] - r.m[1][2], r.m[0][2] - r.m[2][0], r.m[1][0] - r.m[0][1]};
  const double sine2 = length(skew), cosine2 = r.m[0][0] + r.m[1][1] + r.m[2][2] - 1;
  axis = skew / sine2;
  degrees = std::atan2(sine2, cosine2) * 180 / M_PI;
}

struct Case {
  std::string name;
  Mat4 start, end;
  std::function<Mat4(double)> at;  // the pose at t in [0, 1]
};

std::vector<Case> cases() {
  std::vector<Case> out;
  const Vec3 a{-1, 0.5, 2}, b{3, -2, 0.25};
  {
    const Vec3 axis = normalize(Vec3{1, 2, -0.5});
    const Vec3 s0{1, 2, 0.5}, s1{0.25, 1, 3};
    const auto pose = [=](const Vec3& t, double deg, const Vec3& s) {
      return Mat4::translate(t) * Mat4::rotate(deg, axis) * Mat4::scale(s);
    };
    out.push_back({"a turn about one axis, stretching", pose(a, 10, s0), pose(b, 130, s1),
                   [=](double t) { return pose(lerp(a, b, t), lerp(10, 130, t), lerp(s0, s1, t)); }});
  }
  {
    const Mat4 r0 = Mat4::rotate(30, {1, 0, 0}), r1 = Mat4::rotate(100, {1, 2, 3}) * Mat4::rotate(-40, {0, 1, 0});
    Vec3 axis;
    double degrees = 0;
    axis_angle(r0.transposed() * r1, axis, degrees);
    const Vec3 s0{2, 2, 2}, s1{1, 0.5, 1.5};
    out.push_back({"a turn between two axes", Mat4::translate(a) * r0 * Mat4::scale(s0),
                   Mat4::translate(b) * r1 * Mat4::scale(s1), [=](double t) {
                     return Mat4::translate(lerp(a, b, t)) * r0 * Mat4::rotate(t * degrees, axis) *
                            Mat4::scale(lerp(s0, s1, t));
                   }});
  }
  {
    const Vec3 s0{1, 2, 1}, s1{3, 1, 1};
    const auto pose = [=](const Vec3& t, double deg, const Vec3& s) {
      return Mat4::translate(t) * Mat4::rotate(deg, {0, 1, 0}) * Mat4::scale({-1, 1, 1}) * Mat4::scale(s);
    };
    out.push_back({"a mirrored pose", pose(a, 20, s0), pose(b, 80, s1),
                   [=](double t) { return pose(lerp(a, b, t), lerp(20, 80, t), lerp(s0, s1, t)); }});
  }
  {
    const Mat4 r = Mat4::rotate(45, {0, 0, 1});
    out.push_back({"a move without turning", Mat4::translate(a) * r, Mat4::translate(b) * r * Mat4::scale({2, 2, 2}),
                   [=](double t) { return Mat4::translate(lerp(a, b, t)) * r * Mat4::scale(Vec3{1, 1, 1} * lerp(1, 2, t)); }});
  }
  return out;
}

}  // namespace

TEST_CASE("a moving instance's pose at a time is the interpolation of its two poses",
          "[kernels][motion]") {
  const std::vector<Case> all = cases();
  std::vector<dev::InstanceMotion> motions;
  for (const Case& c : all) motions.push_back(device_motion(c.start, c.end));
  CHECK(motions[0].angle_turns > 0);
  CHECK(motions[3].angle_turns == 0);  // equal rotations: the device's linear weights
  const std::vector<float> times = {-0.5f, 0.0f, 0.125f, 0.3f, 0.5f, 0.77f, 1.0f, 1.5f};
  const std::size_t count = all.size() * times.size();
  const Global<dev::f4> rows = allocate<dev::f4>(6 * count);
  run(test_program(kKernel),
      MotionFramesArgs{upload(motions), upload(times), static_cast<cl_uint>(times.size()),
                       static_cast<cl_uint>(count), rows},
      count);
  const std::vector<dev::f4> got = download(rows, 6 * count);
  for (std::size_t c = 0; c < all.size(); ++c)
    for (std::size_t k = 0; k < times.size(); ++k) {
      INFO(all[c].name << " at time " << times[k]);
      const double t = std::min(1.0, std::max(0.0, double{times[k]}));
      const Mat4 inverse = all[c].at(t).inverse();
      const Mat4 normals = inverse.transposed();
      const dev::f4* f = &got[6 * (c * times.size() + k)];
      for (int r = 0; r < 3; ++r) {
        const float to_object[4] = {f[r].x, f[r].y, f[r].z, f[r].w};
        const float normal[4] = {f[3 + r].x, f[3 + r].y, f[3 + r].z, f[3 + r].w};
        for (int j = 0; j < 4; ++j) {
          INFO("row " << r << " column " << j);
          CHECK(to_object[j] == Approx(inverse.m[r][j]).margin(2e-5));
          CHECK(normal[j] == Approx(j < 3 ? normals.m[r][j] : 0.0).margin(2e-5));
        }
      }
    }
}

TEST_CASE("the decomposition gives back each pose", "[kernels][motion]") {
  for (const Case& c : cases()) {
    INFO(c.name);
    for (const Mat4& m : {c.start, c.end}) {
      const Pose p = decompose(m);
      const Quaternion& q = p.rotation;
      // R from the quaternion, times S, plus T, is M again.
      const double rot[3][3] = {
          {1 - 2 * (q.y * q.y + q.z * q.z), 2 * (q.x * q.y - q.w * q.z), 2 * (q.x * q.z + q.w * q.y)},
          {2 * (q.x * q.y + q.w * q.z), 1 - 2 * (q.x * q.x + q.z * q.z), 2 * (q.y * q.z - q.w * q.x)},
          {2 * (q.x * q.z - q.w * q.y), 2 * (q.y * q.z + q.w * q.x), 1 - 2 * (q.x * q.x + q.y * q.y)}};
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          double v = 0;
          for (int k = 0; k < 3; ++k) v += rot[i][k] * p.stretch[3 * k + j];
          CHECK(v == Approx(m.m[i][j]).margin(1e-12));
          CHECK(p.stretch[3 * i + j] == p.stretch[3 * j + i]);
        }
        CHECK(p.translation[i] == m.m[i][3]);
      }
    }
  }
}
