// What each NFF entity puts into the Scene (docs/nff.md has the mapping).
#include <catch2/catch.hpp>
#include <cmath>

#include "scene_test_support.hpp"

using clrt::ShapeKind;
using clrt::Vec3;
using clrt::test::load_text;

namespace {

const double kPi = std::acos(-1.0);

// A view with an 8x8 image, then `rest`.
clrt::Scene load_nff(const std::string& rest) {
  return load_text(
      "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 0.5\nresolution 8 8\n" + rest,
      "scene.nff");
}

double degrees(double radians) { return radians * 180 / kPi; }

}  // namespace

TEST_CASE("NFF: the view places the camera and widens the angle to the image's edges",
          "[scene][nff]") {
  const clrt::Scene s = load_text(
      "v\nfrom 1 2 3\nat 4 5 6\nup 0 0 1\nangle 30\nhither 1\nresolution 20 10\n", "scene.nff");
  CHECK(s.camera.eye == Vec3{1, 2, 3});
  CHECK(s.camera.lookat == Vec3{4, 5, 6});
  CHECK(s.camera.up == Vec3{0, 0, 1});
  CHECK(s.width == 20);
  CHECK(s.height == 10);
  // 30 degrees between the centres of columns 0 and 19, which lie 19 pixels apart; the image is
  // 20 pixels wide.
  const double half_width = std::tan(15 * kPi / 180) * 20 / 19;
  CHECK(s.camera.fov_degrees == Approx(degrees(2 * std::atan(half_width))).epsilon(1e-14));
  // SPD's depth rule, NFF's default background, no ambient light, one sample.
  CHECK(s.max_depth == 4);
  CHECK(s.background == Vec3{0, 0, 0});
  CHECK(s.lights.empty());
  CHECK(s.samples == 1);
}

TEST_CASE("NFF: an image one pixel wide takes the angle as its fov", "[scene][nff]") {
  const clrt::Scene s = load_text(
      "v\nfrom 0 0 1\nat 0 0 0\nup 0 1 0\nangle 30\nhither 0\nresolution 1 5\n", "scene.nff");
  CHECK(s.camera.fov_degrees == 30);
}

TEST_CASE("NFF: b is the background", "[scene][nff]") {
  CHECK(load_nff("b 0.1 0.2 0.3\n").background == Vec3{0.1, 0.2, 0.3});
}

TEST_CASE("NFF: lights without a colour share 1/sqrt(number of lights)", "[scene][nff]") {
  const clrt::Scene s = load_nff("l 1 2 3\nl 4 5 6 0.5 0.25 2\nl 7 8 9\nl 0 0 9\n");
  REQUIRE(s.lights.size() == 4);
  for (const auto& light : s.lights) CHECK(light.kind == "point");
  CHECK(s.lights[0].position == Vec3{1, 2, 3});
  CHECK(s.lights[0].color == Vec3{0.5, 0.5, 0.5});  // 1/sqrt(4), coloured lights counted too
  CHECK(s.lights[1].color == Vec3{0.5, 0.25, 2});
  CHECK(s.lights[1].position == Vec3{4, 5, 6});
  CHECK(s.lights[2].color == Vec3{0.5, 0.5, 0.5});
  const clrt::Scene three = load_nff("l 1 2 3\nl 4 5 6\nl 7 8 9\n");
  CHECK(three.lights[2].color.x == Approx(1 / std::sqrt(3.0)).epsilon(1e-15));
}

TEST_CASE("NFF: f divides the local terms by 1 - Ks - T, Ks is also the reflectivity",
          "[scene][nff]") {
  const clrt::Scene s = load_nff("f 1 0.5 0.25 0.6 0.3 20 0.2 1.5\ns 0 0 0 1\n");
  REQUIRE(s.materials.size() == 2);
  const clrt::MaterialSpec& m = s.materials.at(s.instances.at(0).material);
  CHECK(m.color == Vec3{1, 0.5, 0.25});
  const double w = 1 - 0.3 - 0.2;
  CHECK(m.kd == Approx(0.6 / w).epsilon(1e-15));
  CHECK(m.ks == Approx(0.3 / w).epsilon(1e-15));
  CHECK(m.ka == Approx(0.1 / w).epsilon(1e-15));
  CHECK(m.shininess == 20);
  CHECK(m.kr == 0.3);
  CHECK(m.kt == 0.2);
  CHECK(m.ior == 1.5);
}

TEST_CASE("NFF: with Ks + T >= 1 nothing is left to divide by, and ior <= 0 means 1",
          "[scene][nff]") {
  const clrt::Scene s = load_nff("f 1 1 1 0.1 0.1 101 0.9 1.5\nf 1 1 1 0.5 0.5 5 0.5 0\n");
  const clrt::MaterialSpec& glass = s.materials.at(1);
  CHECK(glass.kd == 0.1);
  CHECK(glass.ks == 0.1);
  CHECK(glass.ka == 0.1);
  CHECK(glass.kr == 0.1);
  CHECK(glass.kt == 0.9);
  CHECK(s.materials.at(2).ior == 1);
}

TEST_CASE("NFF: objects before the first f take clrt's default material", "[scene][nff]") {
  const clrt::Scene s = load_nff("s 0 0 0 1\nf 1 0 0 1 0 0 0 1\ns 0 0 0 1\n");
  CHECK(s.instances.at(0).material == 0);
  CHECK(s.materials.at(0).kd == clrt::MaterialSpec{}.kd);
  CHECK(s.instances.at(1).material == 1);
}

TEST_CASE("NFF: s is a sphere, a negative radius is its size, radius 0 is left out",
          "[scene][nff]") {
  const clrt::Scene s = load_nff("s 1 2 3 0.5\ns -1 0 0 -2\ns 9 9 9 0\n");
  REQUIRE(s.instances.size() == 2);
  const clrt::Mat4& m = s.instances[0].transform;
  CHECK(s.instances[0].shape == ShapeKind::Sphere);
  CHECK(m.transform_point({0, 0, 0}) == Vec3{1, 2, 3});
  CHECK(m.transform_point({1, 0, 0}) == Vec3{1.5, 2, 3});
  CHECK(s.instances[1].transform.transform_point({0, 1, 0}) == Vec3{-1, 2, 0});
  CHECK(s.instances[0].place.line == 8);
}

namespace {

void check_near(const Vec3& got, const Vec3& expected) {
  INFO("got (" << got.x << ", " << got.y << ", " << got.z << "), expected (" << expected.x << ", "
               << expected.y << ", " << expected.z << ")");
  CHECK(length(got - expected) < 1e-12);
}

}  // namespace

TEST_CASE("NFF: c with equal radii is a cylinder from base to apex", "[scene][nff]") {
  const Vec3 base{1, 2, 3}, apex{3, 1, 5};  // an axis of length 3
  const clrt::Scene s = load_nff("c 1 2 3 0.5 3 1 5 0.5\n");
  REQUIRE(s.instances.size() == 1);
  CHECK(s.instances[0].shape == ShapeKind::Cylinder);
  const clrt::Mat4& m = s.instances[0].transform;
  check_near(m.transform_point({0, -1, 0}), base);
  check_near(m.transform_point({0, 1, 0}), apex);
  // A point of the canonical rim lies 0.5 from the base, across the axis.
  for (const Vec3& rim : {Vec3{1, -1, 0}, Vec3{0, -1, 1}}) {
    const Vec3 offset = m.transform_point(rim) - base;
    CHECK(length(offset) == Approx(0.5));
    CHECK(dot(offset, apex - base) == Approx(0).margin(1e-12));
  }
}

TEST_CASE("NFF: c with two radii is a cone scaled by the larger radius", "[scene][nff]") {
  const clrt::Scene s = load_nff("c 0 0 0 0.2 0 0 4 0.8\nc 0 1 0 -2 0 -1 0 -1\n");
  REQUIRE(s.instances.size() == 2);
  const clrt::InstanceSpec& widening = s.instances[0];
  CHECK(widening.shape == ShapeKind::Cone);
  CHECK(widening.cone_r0 == 0.25);
  CHECK(widening.cone_r1 == 1);
  check_near(widening.transform.transform_point({0, -1, 0}), {0, 0, 0});
  check_near(widening.transform.transform_point({0, 1, 0}), {0, 0, 4});
  check_near(widening.transform.transform_point({0, 1, 1}) - Vec3{0, 0, 4}, {0, -0.8, 0});
  // An axis along -y: half a turn; negative radii read as sizes.
  const clrt::InstanceSpec& down = s.instances[1];
  CHECK(down.cone_r0 == 1);
  CHECK(down.cone_r1 == 0.5);
  check_near(down.transform.transform_point({0, -1, 0}), {0, 1, 0});
  check_near(down.transform.transform_point({0, 1, 0}), {0, -1, 0});
  check_near(down.transform.transform_point({1, -1, 0}), {2, 1, 0});
}

TEST_CASE("NFF: a cylinder along +y is not turned, radii 0 are left out", "[scene][nff]") {
  const clrt::Scene s = load_nff("c 0 0 0 1 0 2 0 1\nc 0 0 0 0 1 1 1 0\n");
  REQUIRE(s.instances.size() == 1);
  const clrt::Mat4 expected = clrt::Mat4::translate({0, 1, 0}) * clrt::Mat4::scale({1, 1, 1});
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) CHECK(s.instances[0].transform.m[i][j] == expected.m[i][j]);
}

TEST_CASE("NFF: p becomes loose triangles, numbers on any lines", "[scene][nff]") {
  const clrt::Scene s = load_nff(
      "f 1 0 0 1 0 0 0 1\n"
      "p 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
      "p 3 0 0 1 1 1 1 2 2 1\n"  // no area: left out
      "p 3 5 5 5\n6 5 5 6 6\n5\n");
  REQUIRE(s.triangles.size() == 3);
  CHECK(s.triangles[0].v0 == Vec3{0, 0, 0});
  CHECK(s.triangles[0].v1 == Vec3{1, 0, 0});
  CHECK(s.triangles[0].v2 == Vec3{1, 1, 0});
  CHECK(s.triangles[1].v0 == Vec3{0, 0, 0});
  CHECK(s.triangles[1].v1 == Vec3{1, 1, 0});
  CHECK(s.triangles[1].v2 == Vec3{0, 1, 0});
  CHECK(s.triangles[2].v2 == Vec3{6, 6, 5});
  CHECK(s.triangles[0].material == 1);
  CHECK(s.instances.empty());
}

TEST_CASE("NFF: pp patches go into one mesh per material, with their normals", "[scene][nff]") {
  const clrt::Scene s = load_nff(
      "f 1 0 0 1 0 0 0 1\n"
      "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 2\n0 1 0 0 1 1\n"
      "f 0 1 0 1 0 0 0 1\n"
      "pp 4 0 0 1 0 0 1  1 0 1 0 0 1  1 1 1 0 0 1  0 1 1 0 0 1\n"
      "pp 3 0 0 0 1 0 0  1 1 1 1 0 0  2 2 2 1 0 0\n"  // no area: left out
      "f 1 0 0 1 0 0 0 1\n"
      "pp 3 5 0 0 0 0 1  6 0 0 0 0 1  5 1 0 0 0 1\n");
  REQUIRE(s.meshes.size() == 3);
  REQUIRE(s.instances.size() == 3);
  for (int i = 0; i < 3; ++i) {
    CHECK(s.instances[i].shape == ShapeKind::Mesh);
    CHECK(s.instances[i].mesh == i);
    CHECK(s.instances[i].material == i + 1);
    CHECK(s.instances[i].transform.transform_point({1, 2, 3}) == Vec3{1, 2, 3});
  }
  const clrt::MeshData& first = s.meshes[0];
  CHECK(first.positions == std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  CHECK(first.normals == std::vector<Vec3>{{0, 0, 1}, {0, 0, 2}, {0, 1, 1}});
  CHECK(first.corners == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(first.corner_normals == first.corners);
  CHECK(s.meshes[1].corners == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
  CHECK(s.meshes[2].positions.size() == 3);
  CHECK(s.triangles.empty());
}

TEST_CASE("NFF: names in any case, comments, blank lines and CRLF", "[scene][nff]") {
  const clrt::Scene s = load_text(
      "# a comment line\r\n\r\nV\r\nFROM 0 0 5 # eye\r\nAt 0 0 0\r\nup 0 1 0\r\n"
      "angle 45\r\nhither 0\r\nresolution 8 8\r\nS 0 0 0 1\r\nPP 3 0 0 0 0 0 1 1 0 0 0 0 1 0 1 0 "
      "0 0 1\r\n",
      "scene.nff");
  CHECK(s.instances.size() == 2);
}

TEST_CASE("load_scene reads NFF by the extension .nff in any case, else .ray", "[scene][nff]") {
  const std::string nff = "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 0\nresolution 8 8\n";
  CHECK(load_text(nff, "scene.NFF").width == 8);
  const clrt::SceneError as_ray = clrt::test::load_error(nff, "scene.txt");
  CHECK_THAT(as_ray.message(), Catch::Contains("unknown command 'v'"));
}
