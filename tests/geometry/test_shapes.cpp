// Canonical objects on the device against hits worked out by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "test_shapes_kernel.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

PlacedShape placed(dev::u32 shape, const Mat4& m = {}, double r0 = 1, double r1 = 0) {
  return {shape, r0, r1, m};
}

WorldRay ray(const Vec3& o, const Vec3& d, double tmin = 1e-4, double tmax = kInf) {
  return {o, d, tmin, tmax};
}

DeviceHit cast(const PlacedShape& shape, const WorldRay& r) { return cast_canonical({shape}, {r})[0]; }

void expect_hit(const PlacedShape& shape, const WorldRay& r, double t, const Vec3& normal) {
  check_hit(cast(shape, r), t, normal);
}

void expect_miss(const PlacedShape& shape, const WorldRay& r) { check_miss(cast(shape, r), r); }

}  // namespace

TEST_CASE("sphere: hand-computed hits and misses", "[shapes]") {
  const PlacedShape sphere = placed(CLRT_SHAPE_SPHERE);
  expect_hit(sphere, ray({0, 0, 5}, {0, 0, -1}), 4, {0, 0, 1});
  // From the centre with a direction of length 2: t is in units of the direction.
  expect_hit(sphere, ray({0, 0, 0}, {0, 0, -2}), 0.5, {0, 0, -1});
  // A tangent touches the closed sphere; just above it misses.
  expect_hit(sphere, ray({-5, 1, 0}, {1, 0, 0}), 5, {0, 1, 0});
  expect_miss(sphere, ray({-5, 1.001, 0}, {1, 0, 0}));
  // Both hits behind the origin.
  expect_miss(sphere, ray({0, 0, 5}, {0, 0, 1}));
  // The near hit below tmin: the far one is found.
  expect_hit(sphere, ray({0, 0, 5}, {0, 0, -1}, 4.5), 6, {0, 0, -1});
  // The upper bound is strict and leaves t and the normal alone.
  expect_miss(sphere, ray({0, 0, 5}, {0, 0, -1}, 1e-4, 3.9));
  expect_miss(sphere, ray({0, 0, 5}, {0, 0, -1}, 1e-4, 4));
}

TEST_CASE("sphere: placed by transforms", "[shapes]") {
  // scale 2 then translate 3 0 0: a sphere of radius 2 about (3, 0, 0).
  const Mat4 moved = Mat4::translate({3, 0, 0}) * Mat4::scale({2, 2, 2});
  expect_hit(placed(CLRT_SHAPE_SPHERE, moved), ray({3, 0, 10}, {0, 0, -1}), 8, {0, 0, 1});
  // The ellipsoid x^2 + (y/3)^2 + z^2 = 1 at x = 0.5: y = 3 sqrt(0.75); its gradient is
  // (x, y / 9, z), which is what (M^-1)^T must give.
  const double y = 3 * std::sqrt(0.75);
  expect_hit(placed(CLRT_SHAPE_SPHERE, Mat4::scale({1, 3, 1})), ray({0.5, 10, 0}, {0, -1, 0}),
             10 - y, {0.5, y / 9, 0});
  // A rotation leaves the unit sphere where it was.
  expect_hit(placed(CLRT_SHAPE_SPHERE, Mat4::rotate(73, {1, 2, 3})), ray({0, 0, 5}, {0, 0, -1}), 4,
             {0, 0, 1});
}

TEST_CASE("plane: hand-computed hits and misses", "[shapes]") {
  const PlacedShape plane = placed(CLRT_SHAPE_PLANE);
  expect_hit(plane, ray({0, 2, 0}, {0, -1, 0}), 2, {0, 1, 0});
  // From below: the normal stays +y (the renderer flips it, not the intersector).
  expect_hit(plane, ray({1, -3, 2}, {0, 1, 0}), 3, {0, 1, 0});
  expect_hit(plane, ray({0, 1, 0}, {1, -2, 0}), 0.5, {0, 1, 0});
  // Parallel rays, above the plane and within it: no hit and no 0 / 0.
  expect_miss(plane, ray({0, 1, 0}, {1, 0, 0}));
  expect_miss(plane, ray({0, 0, 0}, {1, 0, 0}));
  expect_miss(plane, ray({0, 2, 0}, {0, 1, 0}));
  // rotatex 90 turns it into z = 0 facing +z; translate 0 -1 0 lowers it.
  expect_hit(placed(CLRT_SHAPE_PLANE, Mat4::rotate(90, {1, 0, 0})), ray({0, 0, 3}, {0, 0, -1}), 3,
             {0, 0, 1});
  expect_hit(placed(CLRT_SHAPE_PLANE, Mat4::translate({0, -1, 0})), ray({0, 2, 0}, {0, -1, 0}), 3,
             {0, 1, 0});
  // A mirror in y carries the normal by (M^-1)^T to -y.
  expect_hit(placed(CLRT_SHAPE_PLANE, Mat4::scale({1, -1, 1})), ray({0, 2, 0}, {0, -1, 0}), 2,
             {0, -1, 0});
}

TEST_CASE("cube: hand-computed hits and misses", "[shapes]") {
  const PlacedShape cube = placed(CLRT_SHAPE_CUBE);
  expect_hit(cube, ray({0, 0, 5}, {0, 0, -1}), 4, {0, 0, 1});
  expect_hit(cube, ray({0.5, 0, 0}, {1, 0, 0}), 0.5, {1, 0, 0});
  expect_miss(cube, ray({0, 0, 5}, {0, 0, 1}));
  // Axis-parallel rays along the top face touch the closed cube; just above they miss.
  expect_hit(cube, ray({-5, 1, 0}, {1, 0, 0}), 4, {-1, 0, 0});
  expect_miss(cube, ray({-5, 1.0001, 0}, {1, 0, 0}));
  expect_miss(cube, ray({-5, 0, 1.5}, {1, 0, 0}));
  // Through a corner: any of the three faces' normals is right.
  const DeviceHit corner = cast(cube, ray({-3, -3, -3}, {1, 1, 1}));
  REQUIRE(corner.hit);
  CHECK(corner.t == Approx(2));
  CHECK(std::min({corner.normal.x, corner.normal.y, corner.normal.z}) == Approx(-1));
  CHECK(corner.normal.x + corner.normal.y + corner.normal.z == Approx(-1));
  // scale 2 1 1, rotatey 90 (x to -z), translate 0 0 -2: x in [-1, 1], z in [-4, 0].
  const Mat4 m = Mat4::translate({0, 0, -2}) * Mat4::rotate(90, {0, 1, 0}) * Mat4::scale({2, 1, 1});
  expect_hit(placed(CLRT_SHAPE_CUBE, m), ray({0, 0, 5}, {0, 0, -1}), 5, {0, 0, 1});
  expect_hit(placed(CLRT_SHAPE_CUBE, m), ray({5, 0, -2}, {-1, 0, 0}), 4, {1, 0, 0});
}

TEST_CASE("cylinder: hand-computed hits and misses", "[shapes]") {
  const PlacedShape cylinder = placed(CLRT_SHAPE_CYLINDER);
  expect_hit(cylinder, ray({0, 0, 5}, {0, 0, -1}), 4, {0, 0, 1});
  expect_hit(cylinder, ray({0.5, 5, 0}, {0, -1, 0}), 4, {0, 1, 0});
  expect_hit(cylinder, ray({0, -5, 0.5}, {0, 1, 0}), 4, {0, -1, 0});
  // From inside: out through the cap, and through the side.
  expect_hit(cylinder, ray({0, 0, 0}, {0, 1, 0}), 1, {0, 1, 0});
  expect_hit(cylinder, ray({0, 0, 0}, {0, 0, -3}), 1.0 / 3, {0, 0, -1});
  // Parallel to the axis: outside misses; along the side touches the cap's rim.
  expect_miss(cylinder, ray({1.5, 5, 0}, {0, -1, 0}));
  expect_hit(cylinder, ray({1, 5, 0}, {0, -1, 0}), 4, {0, 1, 0});
  // Across the axis above the top, and in the plane of the top cap.
  expect_miss(cylinder, ray({-5, 1.5, 0}, {1, 0, 0}));
  expect_hit(cylinder, ray({-5, 1, 0}, {1, 0, 0}), 4, {-1, 0, 0});
  // scale .5 2 .5 then rotatez 90: radius 0.5 about the x axis, x in [-2, 2].
  const Mat4 m = Mat4::rotate(90, {0, 0, 1}) * Mat4::scale({0.5, 2, 0.5});
  expect_hit(placed(CLRT_SHAPE_CYLINDER, m), ray({5, 0, 0}, {-1, 0, 0}), 3, {1, 0, 0});
  expect_hit(placed(CLRT_SHAPE_CYLINDER, m), ray({0, 0, 5}, {0, 0, -1}), 4.5, {0, 0, 1});
}

// The cone's side x^2 + z^2 = R(y)^2, R(y) = m y + k, has the outward normal (x, -m R, z).
TEST_CASE("cone: hand-computed hits and misses", "[shapes]") {
  const PlacedShape cone = placed(CLRT_SHAPE_CONE);  // r0 = 1, r1 = 0: m = -0.5, k = 0.5
  // Down the axis onto the apex: the axis out of the apex stands in for its normal.
  expect_hit(cone, ray({0, 5, 0}, {0, -1, 0}), 4, {0, 1, 0});
  expect_hit(cone, ray({0, 0, 5}, {0, 0, -1}), 4.5, {0, 0.25, 0.5});
  expect_hit(cone, ray({0.3, -5, 0}, {0, 1, 0}), 4, {0, -1, 0});
  expect_hit(cone, ray({0, 0, 0}, {0, 1, 0}), 1, {0, 1, 0});
  // Through the mirror nappe beyond the apex (x^2 + z^2 = R^2 holds there too): no hit.
  expect_miss(cone, ray({-5, 1.5, 0}, {1, 0, 0}));
  expect_miss(cone, ray({-2, 2.5, 0}, {1, -0.1, 0}));
  // Starting inside the mirror nappe, steeper than the cone: the real side at R = 0.1.
  expect_hit(cone, ray({0.1, 3, 0}, {0, -1, 0}), 2.2, {0.1, 0.05, 0});
  // Parallel to a line of the cone (its quadratic term vanishes): inside for t <= 1.75,
  // entering through the bottom cap at t = 1; from t = 1.25 on it leaves at (-0.25, 0.5, 0).
  expect_hit(cone, ray({1.5, -3, 0}, {-1, 2, 0}), 1, {0, -1, 0});
  expect_hit(cone, ray({0.25, -0.5, 0}, {-1, 2, 0}), 0.5, {-0.25, 0.125, 0});
  // Mirrored in y (apex at the bottom): the normal follows (M^-1)^T.
  expect_hit(placed(CLRT_SHAPE_CONE, Mat4::scale({1, -1, 1})), ray({0, 0, 5}, {0, 0, -1}), 4.5,
             {0, -0.25, 0.5});
}

TEST_CASE("cone: frustum and apex at the bottom", "[shapes]") {
  const PlacedShape frustum = placed(CLRT_SHAPE_CONE, {}, 1, 0.5);  // m = -0.25, k = 0.75
  expect_hit(frustum, ray({0, 5, 0.2}, {0, -1, 0}), 4, {0, 1, 0});
  expect_hit(frustum, ray({0, 0, 5}, {0, 0, -1}), 4.25, {0, 0.1875, 0.75});
  // Outside the top cap (radius 0.5): down onto the side where R = 0.6.
  expect_hit(frustum, ray({0.6, 5, 0}, {0, -1, 0}), 4.4, {0.6, 0.15, 0});
  const PlacedShape upside_down = placed(CLRT_SHAPE_CONE, {}, 0, 1);  // m = 0.5, k = 0.5
  expect_hit(upside_down, ray({0, -5, 0}, {0, 1, 0}), 4, {0, -1, 0});
  expect_hit(upside_down, ray({0, 0, 5}, {0, 0, -1}), 4.5, {0, -0.25, 0.5});
  expect_hit(upside_down, ray({0.2, 5, 0}, {0, -1, 0}), 4, {0, 1, 0});
  // No cap where the radius is 0: from below it enters through the side where R = 0.2.
  expect_hit(upside_down, ray({0.2, -5, 0}, {0, 1, 0}), 4.4, {0.2, -0.1, 0});
}

TEST_CASE("a zero direction hits nothing and makes no NaN", "[shapes]") {
  for (const dev::u32 shape : {CLRT_SHAPE_SPHERE, CLRT_SHAPE_PLANE, CLRT_SHAPE_CUBE,
                               CLRT_SHAPE_CYLINDER, CLRT_SHAPE_CONE}) {
    INFO("shape " << shape);
    expect_miss(placed(shape), ray({0, 0, 0}, {0, 0, 0}));
    expect_miss(placed(shape), ray({0, 3, 0}, {0, 0, 0}));
  }
}
