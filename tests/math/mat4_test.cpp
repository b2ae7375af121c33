#include "math/mat4.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using clrt::Mat4;
using clrt::Vec3;

namespace {

void check_identity(const Mat4& m) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      INFO(i << "," << j);
      CHECK(m.m[i][j] == Approx(i == j ? 1.0 : 0.0).margin(1e-12));
    }
}

}  // namespace

TEST_CASE("translate, scale and their product act on points and vectors", "[math][mat4]") {
  const Mat4 m = Mat4::translate({1, 2, 3}) * Mat4::scale({2, 3, 4});
  CHECK(m.transform_point({1, 1, 1}) == Vec3{3, 5, 7});
  CHECK(m.transform_vector({1, 1, 1}) == Vec3{2, 3, 4});
}

TEST_CASE("inverse * M = I for a general affine matrix", "[math][mat4]") {
  const Mat4 m = Mat4::translate({-3, 0.5, 7}) * Mat4::rotate(33, {1, 2, -0.5}) *
                 Mat4::scale({0.25, -2, 5}) * Mat4::rotate(-71, {0, 1, 1});
  check_identity(m.inverse() * m);
  check_identity(m * m.inverse());
}

TEST_CASE("inverse of simple transforms matches the lecture's rules", "[math][mat4]") {
  const Mat4 t = Mat4::translate({1, -2, 3}).inverse();
  CHECK(t.transform_point({0, 0, 0}) == Vec3{-1, 2, -3});
  const Mat4 s = Mat4::scale({2, 4, -8}).inverse();
  CHECK(s.m[0][0] == 0.5);
  CHECK(s.m[1][1] == 0.25);
  CHECK(s.m[2][2] == -0.125);
  // Rotate(theta)^-1 = Rotate(-theta).
  const Mat4 r = Mat4::rotate(40, {1, 1, 0}).inverse();
  const Mat4 expected = Mat4::rotate(-40, {1, 1, 0});
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) CHECK(r.m[i][j] == Approx(expected.m[i][j]).margin(1e-12));
}

TEST_CASE("rotate is right-handed", "[math][mat4]") {
  const Vec3 y = Mat4::rotate(90, {0, 0, 1}).transform_vector({1, 0, 0});
  CHECK(y.x == Approx(0).margin(1e-15));
  CHECK(y.y == Approx(1));
  const Vec3 x = Mat4::rotate(90, {0, 1, 0}).transform_vector({0, 0, 1});
  CHECK(x.x == Approx(1));
  CHECK(x.z == Approx(0).margin(1e-15));
}

TEST_CASE("transposed swaps rows and columns", "[math][mat4]") {
  Mat4 m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m.m[i][j] = 10 * i + j;
  const Mat4 t = m.transposed();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) CHECK(t.m[i][j] == 10 * j + i);
}
