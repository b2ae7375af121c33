// The scenes shipped in scenes/: all of them load, and the lecture's two examples mean what
// the lecture says.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "scene/scene.hpp"

using clrt::ShapeKind;
using clrt::Vec3;

namespace {

const std::filesystem::path kScenes = std::filesystem::path(CLRT_SOURCE_DIR) / "scenes";

clrt::Scene load_shipped(const std::string& name) {
  return clrt::load_scene((kScenes / name).string());
}

// The lowest world y of the unit sphere placed by m: t_y - |row 1 of the 3x3 part|.
double lowest_y_of_unit_sphere(const clrt::Mat4& m) {
  return m.m[1][3] -
         std::sqrt(m.m[1][0] * m.m[1][0] + m.m[1][1] * m.m[1][1] + m.m[1][2] * m.m[1][2]);
}

}  // namespace

TEST_CASE("every .ray and .nff file in scenes/ loads", "[scene][shipped]") {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kScenes))
    if (entry.path().extension() == ".ray" || entry.path().extension() == ".nff")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  CHECK(files.size() >= 21);
  for (const auto& file : files) {
    INFO(file.string());
    CHECK_NOTHROW(clrt::load_scene(file.string()));
  }
}

TEST_CASE("reflect.ray: the small spheres rest on the plane y = -1", "[scene][shipped]") {
  const clrt::Scene s = load_shipped("reflect.ray");
  REQUIRE(s.instances.size() == 5);
  for (int i = 0; i < 3; ++i) {
    INFO("sphere " << i);
    CHECK(s.instances[i].shape == ShapeKind::Sphere);
    CHECK(lowest_y_of_unit_sphere(s.instances[i].transform) == Approx(-1.0));
  }
  // The large mirror sphere floats above the plane.
  CHECK(lowest_y_of_unit_sphere(s.instances[3].transform) == Approx(-0.75));
  CHECK(s.instances[4].shape == ShapeKind::Plane);
  CHECK(s.instances[4].transform.transform_point({0, 0, 0}) == Vec3{0, -1, 0});
  // The red sphere of the lecture's transform-order example is centred at (-2, -0.5, 0).
  CHECK(s.instances[0].transform.transform_point({0, 0, 0}) == Vec3{-2, -0.5, 0});
}

TEST_CASE("reflect.ray: its materials in the 10- and 11-number spellings", "[scene][shipped]") {
  const clrt::Scene s = load_shipped("reflect.ray");
  REQUIRE(s.materials.size() == 6);
  const clrt::MaterialSpec& green = s.materials[s.instances[1].material];
  CHECK(green.color == Vec3{0, 1, 0});
  CHECK(green.ka == 0.3);
  CHECK(green.kd == 0.7);
  CHECK(green.ks == 0.5);
  CHECK(green.shininess == 100);
  CHECK(green.kr == 0.5);
  CHECK(green.ior == 1);
  const clrt::MaterialSpec& mirror = s.materials[s.instances[3].material];
  CHECK(mirror.color == Vec3{1, 1, 1});
  CHECK(mirror.kr == 0.8);
  CHECK(s.camera.eye == Vec3{-2, 1.5, 10});
  CHECK(s.camera.fov_degrees == 45);
  REQUIRE(s.lights.size() == 2);
  CHECK(s.lights[1].position == Vec3{5, 9, 10});
}

TEST_CASE("test2.ray: the lecture's first example with its light repaired", "[scene][shipped]") {
  const clrt::Scene s = load_shipped("test2.ray");
  CHECK(s.width == 500);
  CHECK(s.height == 300);
  CHECK(s.background == Vec3{0.5, 0, 0.5});
  REQUIRE(s.instances.size() == 1);
  CHECK(s.materials[s.instances[0].material].color == Vec3{0, 1, 0});
  REQUIRE(s.lights.size() == 2);
  CHECK(s.lights[0].kind == "ambient");
  CHECK(s.lights[1].kind == "point");
  CHECK(s.lights[1].color == Vec3{0.6, 0.6, 0.6});
  CHECK(s.lights[1].position == Vec3{3, 3, 3});
}

TEST_CASE("the SPD scenes in scenes/spd load with their primitive counts", "[scene][shipped]") {
  const clrt::Scene balls = load_shipped("spd/balls-1.ray");
  CHECK(balls.instances.size() == 10);
  CHECK(balls.triangles.size() == 2);
  CHECK(balls.lights.size() == 3);
  const clrt::Scene tetra = load_shipped("spd/tetra-2.ray");
  CHECK(tetra.triangles.size() == 16);
  CHECK(tetra.instances.empty());
  CHECK(tetra.width == 512);
}
