#include <catch2/catch.hpp>

#include "scene_test_support.hpp"

using clrt::MaterialSpec;
using clrt::Vec3;
using clrt::test::load_text;
using clrt::test::require_error;

namespace {

void check_material(const MaterialSpec& m, Vec3 color, double ka, double kd, double ks, double n,
                    double kr, double kt, double ior) {
  CHECK(m.color == color);
  CHECK(m.ka == ka);
  CHECK(m.kd == kd);
  CHECK(m.ks == ks);
  CHECK(m.shininess == n);
  CHECK(m.kr == kr);
  CHECK(m.kt == kt);
  CHECK(m.ior == ior);
}

}  // namespace

TEST_CASE("the default material is 1 1 1 0.2 0.8 0 1 0 0 1 at index 0", "[scene][material]") {
  const clrt::Scene s = load_text("sphere\n");
  REQUIRE(s.materials.size() == 1);
  check_material(s.materials[0], {1, 1, 1}, 0.2, 0.8, 0, 1, 0, 0, 1);
  CHECK(s.instances.at(0).material == 0);
}

TEST_CASE("the three material spellings", "[scene][material]") {
  const clrt::Scene s = load_text(
      "material 0 1 0 .3 .7 0 0 0 0\n"                   // 9: r g b ka kd ks n kr kt
      "material 1 0 0 0.3 .7 .5 100 .5 0 1.5\n"          // 10: ... ior
      "material 0 0 1 0.25 0.3 .7 .5 100 .5 .25 1.33\n"  // 11: r g b a ka kd ks n kr kt ior
  );
  REQUIRE(s.materials.size() == 4);
  check_material(s.materials[1], {0, 1, 0}, 0.3, 0.7, 0, 0, 0, 0, 1);
  check_material(s.materials[2], {1, 0, 0}, 0.3, 0.7, 0.5, 100, 0.5, 0, 1.5);
  check_material(s.materials[3], {0, 0, 1}, 0.3, 0.7, 0.5, 100, 0.5, 0.25, 1.33);
}

TEST_CASE("surface is a synonym of material", "[scene][material]") {
  const clrt::Scene s = load_text("SURFACE .1 .2 .3 .4 .5 .6 7 .8 .1\n");
  REQUIRE(s.materials.size() == 2);
  check_material(s.materials[1], {0.1, 0.2, 0.3}, 0.4, 0.5, 0.6, 7, 0.8, 0.1, 1);
}

TEST_CASE("an ior <= 0 means 1", "[scene][material]") {
  const clrt::Scene s =
      load_text("material 1 1 1 .2 .8 0 1 0 0 0\nmaterial 1 1 1 .2 .8 0 1 0 0 -2\n");
  CHECK(s.materials[1].ior == 1);
  CHECK(s.materials[2].ior == 1);
}

TEST_CASE("objects take the current material, each material command appends one",
          "[scene][material]") {
  const clrt::Scene s = load_text(
      "sphere\nmaterial 1 0 0 .2 .8 0 1 0 0\nplane\ncube\nmaterial 0 1 0 .2 .8 0 1 0 0\n"
      "triangle 0 0 0 1 0 0 0 1 0\nmaterial 1 0 0 .2 .8 0 1 0 0\ncone\n");
  REQUIRE(s.materials.size() == 4);
  REQUIRE(s.instances.size() == 4);
  CHECK(s.instances[0].material == 0);
  CHECK(s.instances[1].material == 1);
  CHECK(s.instances[2].material == 1);
  CHECK(s.instances[3].material == 3);
  CHECK(s.triangles.at(0).material == 2);
}

TEST_CASE("kr and kt must lie in [0, 1]", "[scene][material][errors]") {
  // 9-number form: kr is the 8th number, kt the 9th.
  require_error("material 1 1 1 .2 .8 0 1 1.5 0\n", 1, 26, "kr must be in [0, 1]");
  require_error("material 1 1 1 .2 .8 0 1 0 -0.1\n", 1, 28, "kt must be in [0, 1]");
  // 11-number form: kr and kt move one word to the right.
  require_error("material 1 1 1 0 .2 .8 0 1 0 2 1\n", 1, 30, "kt must be in [0, 1]");
  CHECK(load_text("material 1 1 1 .2 .8 0 1 1 1\n").materials[1].kt == 1);
}

TEST_CASE("a negative Phong exponent is an error", "[scene][material][errors]") {
  require_error("material 1 1 1 .2 .8 0 -1 0 0\n", 1, 24, "Phong exponent must be >= 0");
  CHECK(load_text("material 1 1 1 .2 .8 0 0 0 0\n").materials[1].shininess == 0);
}

TEST_CASE("material argument counts and non-numbers", "[scene][material][errors]") {
  require_error("material 1 1 1 .2 .8 0 1 0\n", 1, 27, "takes 9, 10 or 11 arguments, found 8");
  require_error("material 1 1 1 1 .2 .8 0 1 0 0 1 9\n", 1, 34, "found 12");
  require_error("material 1 1 1 x .2 .8 0 1 0 0 1\n", 1, 16, "expected a number");
}

TEST_CASE("emission gives the objects after it a glowing copy of the current material",
          "[scene][material]") {
  const clrt::Scene s = load_text(
      "material 1 0 0 .2 .8 0 1 0 0\nsphere\nemission 1 2 3\ncube\nemission 0.5 0 0\nplane\n"
      "material 0 1 0 .2 .8 0 1 0 0\ncone\n");
  REQUIRE(s.materials.size() == 5);
  REQUIRE(s.instances.size() == 4);
  CHECK(s.instances[0].material == 1);
  CHECK(s.materials[1].emission == Vec3{0, 0, 0});
  CHECK(s.instances[1].material == 2);
  check_material(s.materials[2], {1, 0, 0}, 0.2, 0.8, 0, 1, 0, 0, 1);
  CHECK(s.materials[2].emission == Vec3{1, 2, 3});
  CHECK(s.instances[2].material == 3);
  CHECK(s.materials[3].emission == Vec3{0.5, 0, 0});
  CHECK(s.instances[3].material == 4);
  CHECK(s.materials[4].emission == Vec3{0, 0, 0});  // the next material starts without it
  // Before any material, the default one glows.
  const clrt::Scene d = load_text("emission 1 1 1\nsphere\n");
  check_material(d.materials.at(1), {1, 1, 1}, 0.2, 0.8, 0, 1, 0, 0, 1);
  CHECK(d.materials[1].emission == Vec3{1, 1, 1});
}

TEST_CASE("emission takes three numbers, none negative", "[scene][material][errors]") {
  require_error("emission 1 1\n", 1, 13, "takes 3 arguments, found 2");
  require_error("emission 1 -1 1\n", 1, 12, "G must be in [0, ");
  require_error("emission 1 1 x\n", 1, 14, "expected a number");
}
