#include <catch2/catch.hpp>
#include <cmath>

#include "scene_test_support.hpp"

using clrt::Mat4;
using clrt::Vec3;
using clrt::test::load_text;
using clrt::test::require_error;

namespace {

// Checks the 3x4 affine part of `m` against `expected`, row by row.
void check_affine(const Mat4& m, const double (&expected)[3][4]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      INFO("row " << i << " column " << j);
      CHECK(m.m[i][j] == Approx(expected[i][j]).margin(1e-12));
    }
  CHECK(m.m[3][0] == 0);
  CHECK(m.m[3][1] == 0);
  CHECK(m.m[3][2] == 0);
  CHECK(m.m[3][3] == 1);
}

Mat4 transform_of(const std::string& commands) {
  const clrt::Scene s = load_text(commands + "\nsphere\n");
  return s.instances.at(0).transform;
}

const double kDeg30 = M_PI / 6;

}  // namespace

TEST_CASE("each transform is applied after the earlier ones (the lecture's example)",
          "[scene][transform]") {
  // scale .5 then translate -2 -.5 0: centre (-2, -0.5, 0), radius 0.5.
  check_affine(transform_of("scale .5 .5 .5\ntranslate -2 -.5 0"),
               {{0.5, 0, 0, -2}, {0, 0.5, 0, -0.5}, {0, 0, 0.5, 0}});
  // The other order scales the translation too.
  check_affine(transform_of("translate -2 -.5 0\nscale .5 .5 .5"),
               {{0.5, 0, 0, -1}, {0, 0.5, 0, -0.25}, {0, 0, 0.5, 0}});
}

TEST_CASE("translate then rotate moves the object around the world origin", "[scene][transform]") {
  const Vec3 a = transform_of("rotatez 90\ntranslate 1 0 0").transform_point({0, 0, 0});
  CHECK(a.x == Approx(1));
  CHECK(a.y == Approx(0).margin(1e-12));
  const Vec3 b = transform_of("translate 1 0 0\nrotatez 90").transform_point({0, 0, 0});
  CHECK(b.x == Approx(0).margin(1e-12));
  CHECK(b.y == Approx(1));
}

TEST_CASE("reset returns to the identity, objects keep the transform they were made with",
          "[scene][transform]") {
  const clrt::Scene s = load_text("translate 1 2 3\nsphere\nreset\nsphere\nscale 2 2 2\nplane\n");
  REQUIRE(s.instances.size() == 3);
  check_affine(s.instances[0].transform, {{1, 0, 0, 1}, {0, 1, 0, 2}, {0, 0, 1, 3}});
  check_affine(s.instances[1].transform, {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}});
  check_affine(s.instances[2].transform, {{2, 0, 0, 0}, {0, 2, 0, 0}, {0, 0, 2, 0}});
}

TEST_CASE("rotatex, rotatey and rotatez match the lecture's matrices", "[scene][transform]") {
  const double c = std::cos(kDeg30), s = std::sin(kDeg30);
  check_affine(transform_of("rotatex 30"), {{1, 0, 0, 0}, {0, c, -s, 0}, {0, s, c, 0}});
  check_affine(transform_of("ROTATEY 30"), {{c, 0, s, 0}, {0, 1, 0, 0}, {-s, 0, c, 0}});
  check_affine(transform_of("rotatez 30"), {{c, -s, 0, 0}, {s, c, 0, 0}, {0, 0, 1, 0}});
}

TEST_CASE("rotate about an arbitrary axis", "[scene][transform]") {
  // 120 degrees about (1,1,1) cycles the axes: x -> y, y -> z, z -> x.
  check_affine(transform_of("rotate 120 1 1 1"), {{0, 0, 1, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}});
  // The axis need not be unit length, and -90 about -z is +90 about +z.
  check_affine(transform_of("rotate -90 0 0 -2"), {{0, -1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}});
  // 180 degrees about (1,1,0)/sqrt2 swaps x and y and negates z.
  check_affine(transform_of("rotate 180 3 3 0"), {{0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, -1, 0}});
}

TEST_CASE("instances carry M, which their inverse undoes", "[scene][transform]") {
  const clrt::Scene s = load_text("scale 1 2 4\nrotate 35 1 -2 0.5\ntranslate 3 -1 2\ncube\n");
  const clrt::InstanceSpec& inst = s.instances.at(0);
  const Mat4 inverse = inst.transform.inverse();
  const Mat4 product = inverse * inst.transform;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) CHECK(product.m[i][j] == Approx(i == j ? 1 : 0).margin(1e-12));
  // The scale is undone: the inverse maps the world point M(1,1,1) back.
  const Vec3 back = inverse.transform_point(inst.transform.transform_point({1, 1, 1}));
  CHECK(back.x == Approx(1));
  CHECK(back.y == Approx(1));
  CHECK(back.z == Approx(1));
}

TEST_CASE("a zero scale factor is an error at that factor", "[scene][transform][errors]") {
  require_error("scale 1 0 1\n", 1, 9, "scale factor must not be 0");
  require_error("scale 0.0 1 1\n", 1, 7, "scale factor must not be 0");
  require_error("scale 1 1 -0\n", 1, 11, "scale factor must not be 0");
  // Negative factors mirror and are allowed.
  check_affine(transform_of("scale -1 1 1"), {{-1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}});
}

TEST_CASE("a zero-length rotation axis is an error at the axis", "[scene][transform][errors]") {
  require_error("rotate 45 0 0 0\n", 1, 11, "rotation axis must not be a zero-length vector");
}

TEST_CASE("transform argument counts", "[scene][transform][errors]") {
  require_error("rotate 45 0 1\n", 1, 14, "rotate takes 4 arguments, found 3");
  require_error("rotatex\n", 1, 8, "rotatex takes 1 argument, found 0");
  require_error("rotatey 1 2\n", 1, 11, "found 2");
  require_error("rotatez 1 2 3\n", 1, 11, "found 3");
  require_error("translate\n", 1, 10, "found 0");
}

TEST_CASE("a transform too extreme to invert is an error at the object",
          "[scene][transform][errors]") {
  require_error("scale 1e-200 1e-200 1e-200\nscale 1e-200 1e-200 1e-200\n  sphere\n", 3, 3,
                "cannot be inverted");
  std::string growing;
  for (int i = 0; i < 26; ++i) growing += "scale 1e12 1 1\n";  // 1e312: the product overflows
  require_error(growing + "cube\n", 27, 1, "cannot be inverted");
}

TEST_CASE("endpose: the transform at endpose is an object's first pose, the current one its "
          "second",
          "[scene][transform][motion]") {
  const clrt::Scene s = load_text(
      "translate -1 0 0\nendpose\ntranslate 2 0 0\nsphere\nsphere 0 1 0 0.5\nreset\nsphere\n"
      "endpose\ncube\nscale 2 2 2\nendpose\ncylinder\n");
  REQUIRE(s.instances.size() == 5);
  REQUIRE(s.end_transforms.size() == 2);
  // The sphere moves from x = -1 to x = +1; so does the next one, which places itself on top.
  check_affine(s.instances[0].transform, {{1, 0, 0, -1}, {0, 1, 0, 0}, {0, 0, 1, 0}});
  REQUIRE(s.instances[0].motion == 0);
  check_affine(s.end_transforms[0], {{1, 0, 0, 1}, {0, 1, 0, 0}, {0, 0, 1, 0}});
  REQUIRE(s.instances[1].motion == 1);
  check_affine(s.instances[1].transform, {{0.5, 0, 0, -1}, {0, 0.5, 0, 1}, {0, 0, 0.5, 0}});
  check_affine(s.end_transforms[1], {{0.5, 0, 0, 1}, {0, 0.5, 0, 1}, {0, 0, 0.5, 0}});
  // reset clears the motion; endpose with nothing after it, or again after a change, leaves
  // the objects still.
  CHECK(s.instances[2].motion == -1);
  CHECK(s.instances[3].motion == -1);
  CHECK(s.instances[4].motion == -1);
  check_affine(s.instances[4].transform, {{2, 0, 0, 0}, {0, 2, 0, 0}, {0, 0, 2, 0}});
}

TEST_CASE("shutter: when the camera's samples are taken, 0 to 1 unless set", "[scene][camera][motion]") {
  CHECK(load_text("").camera.shutter_open == 0);
  CHECK(load_text("").camera.shutter_close == 1);
  const clrt::Scene s = load_text("SHUTTER 0.25 0.75\n");
  CHECK(s.camera.shutter_open == 0.25);
  CHECK(s.camera.shutter_close == 0.75);
  CHECK(load_text("shutter 2 2\n").camera.shutter_open == 2);
}

TEST_CASE("motion errors: a shutter closing before it opens, mirrored poses, moving triangles "
          "and environments",
          "[scene][transform][motion][errors]") {
  require_error("shutter 1 0.5\n", 1, 11, "the shutter must close at or after it opens");
  require_error("shutter 1\n", 1, 10, "wrong number of arguments");
  require_error("endpose 1\n", 1, 9, "wrong number of arguments");
  require_error("endpose\nscale -1 1 1\nsphere\n", 3, 1, "differ in handedness");
  require_error("translate 1 0 0\nendpose\ntranslate 0 1 0\ntriangle 0 0 0 1 0 0 0 1 0\n", 4, 1,
                "a triangle cannot move");
  require_error("endpose\nrotatey 30\nenvironment sky.pfm\n", 3, 13, "the environment cannot move");
  // Still after reset, or before any change.
  CHECK(load_text("endpose\ntriangle 0 0 0 1 0 0 0 1 0\n").triangles.size() == 1);
  CHECK(load_text("endpose\ntranslate 1 0 0\nreset\ntriangle 0 0 0 1 0 0 0 1 0\n").triangles.size() == 1);
}

TEST_CASE("a turn of 180 degrees or more after endpose is a warning at the rotation that makes it",
          "[scene][transform][motion]") {
  const auto warnings = [](const std::string& text) { return load_text(text).warnings; };
  const std::string shorter = ", but a motion takes the shorter way between its two poses: the objects that follow ";
  const auto warned = [&](const std::string& text, const std::string& place, const std::string& message) {
    INFO(text);
    const std::vector<std::string> w = warnings(text);
    REQUIRE(w.size() == 1);
    CHECK_THAT(w[0], Catch::EndsWith("scene.ray:" + place + ": warning: the rotations after endpose come to " +
                                     message));
  };
  warned("endpose\nrotatey 200\nsphere\nsphere\n", "2:1", "200 degrees" + shorter + "turn 160 degrees the other way");
  // Turns about one axis add up exactly, whichever way its axis is written.
  warned("endpose\nrotatey 100\ntranslate 1 0 0\nrotate 100 0 2 0\nsphere\n", "4:1",
         "200 degrees" + shorter + "turn 160 degrees the other way");
  warned("endpose\nrotatey 100\nrotate -100 0 -1 0\nsphere\n", "3:1", "200 degrees" + shorter + "turn 160 degrees the other way");
  warned("endpose\nrotatez 360\ncube\n", "2:1", "360 degrees" + shorter + "do not turn at all");
  warned("endpose\nrotatex -600\ncube\n", "2:1", "-600 degrees" + shorter + "turn 120 degrees the other way");
  warned("endpose\nrotatex 400\ncube\n", "2:1", "400 degrees" + shorter + "turn 40 degrees");
  warned("endpose\nrotatey 180\nsphere\n", "2:1", "180 degrees" + shorter + "turn 180 degrees, either way round");
  // About several axes, by the turn they compose to.
  warned("endpose\nrotatex 170\nrotatey 1\nrotatex 20\nsphere\n", "4:1",
         "a turn of 180 degrees or more" + shorter + "turn 170 degrees the other way");
  // Once per rotation that takes the turn past, for the objects that follow it.
  const std::vector<std::string> two = warnings("endpose\nrotatey 200\nsphere\nrotatey -100\nsphere\nrotatey 100\nsphere\n");
  REQUIRE(two.size() == 2);
  CHECK_THAT(two[0], Catch::Contains("scene.ray:2:1: warning:"));
  CHECK_THAT(two[1], Catch::Contains("scene.ray:6:1: warning:"));
  // A turn under 180 degrees, one taken back, one before endpose, one cleared, or one nothing
  // follows renders as written.
  for (const char* text : {"endpose\nrotatey 179\nsphere\n", "endpose\nrotatex 120\nrotatey 120\nsphere\n",
                           "endpose\nrotatey 200\nrotatey -100\nsphere\n", "rotatey 200\nendpose\nsphere\n",
                           "endpose\nrotatey 200\nreset\nsphere\n", "endpose\nrotatey 200\nendpose\nsphere\n",
                           "endpose\nrotatey 200\n"}) {
    INFO(text);
    CHECK(warnings(text).empty());
  }
}
