// Each NFF file loads into the same Scene as its .ray twin.
#include "nff_twins.hpp"

#include <catch2/catch.hpp>

#include "scene/scene.hpp"
#include "scene_equivalence.hpp"

using clrt::test::nff_twins;
using clrt::test::scene_difference;

namespace {

// The SPD twins hold 9 significant digits (rotations and fovs computed from them), and their OBJ
// files are read into floats: 1e-6 of each value's size covers both, and nothing coarser.
constexpr double kTolerance = 1e-6;

}  // namespace

TEST_CASE("every NFF file loads into the same Scene as its .ray twin", "[scene][nff][twins]") {
  for (const auto& twin : nff_twins()) {
    INFO(twin.nff);
    const clrt::Scene nff = clrt::load_scene(twin.nff), ray = clrt::load_scene(twin.ray);
    CHECK(scene_difference(nff, ray, kTolerance) == "");
  }
}

TEST_CASE("the Scene comparison sees a change of each kind", "[scene][nff][twins]") {
  const auto twins = nff_twins();
  const clrt::Scene tree = clrt::load_scene(twins.at(2).nff);
  REQUIRE(scene_difference(tree, tree, kTolerance) == "");
  auto changed = [&](auto&& change) {
    clrt::Scene copy = tree;
    change(copy);
    return scene_difference(tree, copy, kTolerance);
  };
  CHECK(changed([](clrt::Scene& s) { s.camera.fov_degrees += 1e-4; }) != "");
  CHECK(changed([](clrt::Scene& s) { s.lights.pop_back(); }) != "");
  CHECK(changed([](clrt::Scene& s) { s.lights[0].color.x *= 1.00001; }) != "");
  CHECK(changed([](clrt::Scene& s) { s.instances[0].transform.m[1][3] += 1e-5; }) != "");
  CHECK(changed([](clrt::Scene& s) { s.instances[0].cone_r1 *= 1.001; }) != "");
  CHECK(changed([](clrt::Scene& s) { s.materials[s.instances[1].material].kd += 1e-3; }) != "");
  CHECK(changed([](clrt::Scene& s) { s.triangles[0].v1.y += 1e-4; }) != "");
  CHECK(changed([](clrt::Scene& s) { std::swap(s.triangles[0].v1, s.triangles[0].v2); }) != "");
  CHECK(changed([](clrt::Scene& s) { s.triangles.pop_back(); }) != "");
  const clrt::Scene teapot = clrt::load_scene(twins.at(4).nff);
  REQUIRE_FALSE(teapot.meshes.empty());
  clrt::Scene bent = teapot;
  bent.meshes[0].normals[0].z += 1e-4;
  CHECK(scene_difference(teapot, bent, kTolerance) != "");
  // Corners rotated keep the triangle and its front side.
  CHECK(changed([](clrt::Scene& s) {
          auto& t = s.triangles[0];
          t = {t.v1, t.v2, t.v0, t.material};
        }) == "");
}
