#include <catch2/catch.hpp>

#include "scene_test_support.hpp"

using clrt::ShapeKind;
using clrt::Vec3;
using clrt::test::load_text;
using clrt::test::require_error;

TEST_CASE("every object command makes an instance of its canonical shape", "[scene][objects]") {
  const clrt::Scene s = load_text("sphere\nPlane\ncube\ncylinder\ncone\n");
  REQUIRE(s.instances.size() == 5);
  CHECK(s.instances[0].shape == ShapeKind::Sphere);
  CHECK(s.instances[1].shape == ShapeKind::Plane);
  CHECK(s.instances[2].shape == ShapeKind::Cube);
  CHECK(s.instances[3].shape == ShapeKind::Cylinder);
  CHECK(s.instances[4].shape == ShapeKind::Cone);
  CHECK(s.instances[1].place.line == 2);
  CHECK(s.instances[1].place.column == 1);
  CHECK(s.instances[0].mesh == -1);
}

TEST_CASE("an instance remembers where it was written", "[scene][objects]") {
  const clrt::Scene s = load_text("\n\n   cube\n");
  CHECK(s.instances.at(0).place.line == 3);
  CHECK(s.instances.at(0).place.column == 4);
  CHECK_THAT(clrt::instance_location(s, s.instances.at(0)).file, Catch::EndsWith("scene.ray"));
}

TEST_CASE("sphere x y z r is the sphere of radius r at (x,y,z), then placed by M",
          "[scene][objects]") {
  const clrt::Scene s = load_text("translate 1 0 0\nsphere 0 2 0 3\n");
  const clrt::Mat4& m = s.instances.at(0).transform;
  // M * T(0,2,0) * S(3): centre (1, 2, 0), radius 3.
  CHECK(m.transform_point({0, 0, 0}) == Vec3{1, 2, 0});
  CHECK(m.transform_point({1, 0, 0}) == Vec3{4, 2, 0});
  CHECK(m.transform_point({0, -1, 0}) == Vec3{1, -1, 0});
}

TEST_CASE("a sphere radius must be > 0", "[scene][objects][errors]") {
  require_error("sphere 0 0 0 0\n", 1, 14, "radius must be > 0");
  require_error("sphere 0 0 0 -1\n", 1, 14, "radius must be > 0");
}

TEST_CASE("sphere takes 0 or 4 numbers", "[scene][objects][errors]") {
  require_error("sphere 1 2\n", 1, 11, "sphere takes 0 or 4 arguments, found 2");
  require_error("sphere 1 2 3 4 5\n", 1, 16, "found 5");
}

TEST_CASE("plane, cube and cylinder take no arguments", "[scene][objects][errors]") {
  require_error("cube 1\n", 1, 6, "cube takes 0 arguments");
  require_error("cylinder 1 2\n", 1, 10, "cylinder takes 0 arguments");
}

TEST_CASE("cone radii", "[scene][objects]") {
  const clrt::Scene s = load_text("cone\ncone 0.5 0.25\ncone 0 2\n");
  REQUIRE(s.instances.size() == 3);
  CHECK(s.instances[0].cone_r0 == 1);
  CHECK(s.instances[0].cone_r1 == 0);
  CHECK(s.instances[1].cone_r0 == 0.5);
  CHECK(s.instances[1].cone_r1 == 0.25);
  CHECK(s.instances[2].cone_r0 == 0);
  CHECK(s.instances[2].cone_r1 == 2);
}

TEST_CASE("cone radii must be >= 0 and not both 0", "[scene][objects][errors]") {
  require_error("cone -1 1\n", 1, 6, "cone radius must be >= 0");
  require_error("cone 1 -0.5\n", 1, 8, "cone radius must be >= 0");
  require_error("cone 0 0\n", 1, 6, "must not both be 0");
  require_error("cone 1\n", 1, 7, "cone takes 0 or 2 arguments, found 1");
  require_error("cone 1 1 1\n", 1, 10, "found 3");
}

TEST_CASE("triangle vertices are transformed to world space by M", "[scene][objects]") {
  const clrt::Scene s = load_text(
      "material 1 0 0 .2 .8 0 1 0 0\nscale 2 2 2\ntranslate 0 0 1\ntriangle 0 0 0 1 0 0 0 1 0\n");
  REQUIRE(s.triangles.size() == 1);
  CHECK(s.instances.empty());
  CHECK(s.triangles[0].v0 == Vec3{0, 0, 1});
  CHECK(s.triangles[0].v1 == Vec3{2, 0, 1});
  CHECK(s.triangles[0].v2 == Vec3{0, 2, 1});
  CHECK(s.triangles[0].material == 1);
}

TEST_CASE("triangle takes 9 numbers, or 15 with (u, v) at each corner", "[scene][objects][errors]") {
  require_error("triangle 0 0 0 1 0 0 0 1\n", 1, 25, "triangle takes 9 or 15 arguments, found 8");
  // Between the two counts: just past the last word, as for every command of several counts.
  require_error("triangle 0 0 0 1 0 0 0 1 0 7\n", 1, 29, "found 10");
  require_error("triangle 0 0 0 0 0 1 0 0 1 0 0 1 0 0 1 9\n", 1, 40, "found 16");
  require_error("triangle 0 0 0 1 0 0 0 y 0\n", 1, 24, "expected a number");
}

TEST_CASE("an instance record keeps only what cannot be derived", "[scene][objects][limits]") {
  // Loading a scene of spheres costs this per sphere, plus its line of text: the loader's
  // memory estimate and docs/reliability.md count on it.
  STATIC_REQUIRE(sizeof(clrt::InstanceSpec) <= 168);
}
