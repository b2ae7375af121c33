#include <catch2/catch.hpp>

#include "scene_test_support.hpp"

using clrt::Vec3;
using clrt::test::load_text;
using clrt::test::require_error;

TEST_CASE("camera and image defaults", "[scene][camera]") {
  const clrt::Scene s = load_text("");
  CHECK(s.camera.eye == Vec3{0, 0, 5});
  CHECK(s.camera.lookat == Vec3{0, 0, 0});
  CHECK(s.camera.up == Vec3{0, 1, 0});
  CHECK(s.camera.fov_degrees == 60);
  CHECK(s.background == Vec3{0, 0, 0});
  CHECK(s.width == 500);
  CHECK(s.height == 300);
  CHECK(s.max_depth == 5);
  CHECK(s.samples == 1);
  CHECK(s.instances.empty());
  CHECK(s.lights.empty());
}

TEST_CASE("camera and image commands, case-insensitive", "[scene][camera]") {
  const clrt::Scene s = load_text(
      "EYE 1 2 3\nLookAt 4 5 6\nup 0 0 2\nfov 45.5\nbackground .5 0 0.25\n"
      "resolution 640 480\nmaxdepth 0\nSamples 4\n");
  CHECK(s.camera.eye == Vec3{1, 2, 3});
  CHECK(s.camera.lookat == Vec3{4, 5, 6});
  CHECK(s.camera.up == Vec3{0, 0, 2});
  CHECK(s.camera.fov_degrees == 45.5);
  CHECK(s.background == Vec3{0.5, 0, 0.25});
  CHECK(s.width == 640);
  CHECK(s.height == 480);
  CHECK(s.max_depth == 0);
  CHECK(s.samples == 4);
}

TEST_CASE("a later camera command replaces an earlier one", "[scene][camera]") {
  const clrt::Scene s = load_text("fov 30\nfov 90\nresolution 10 10\nresolution 2 3\n");
  CHECK(s.camera.fov_degrees == 90);
  CHECK(s.width == 2);
  CHECK(s.height == 3);
}

TEST_CASE("whole-number settings accept integral spellings like 2.0 and 1e1", "[scene][camera]") {
  const clrt::Scene s = load_text("resolution 2.0 1e1\nsamples 16.\n");
  CHECK(s.width == 2);
  CHECK(s.height == 10);
  CHECK(s.samples == 16);
}

TEST_CASE("fov must be strictly between 0 and 180", "[scene][camera][errors]") {
  require_error("fov 0\n", 1, 5, "fov must be > 0 and < 180");
  require_error("\nfov   180\n", 2, 7, "fov must be > 0 and < 180");
  require_error("fov -10\n", 1, 5, "fov");
  CHECK(load_text("fov 179.9\n").camera.fov_degrees == 179.9);
  CHECK(load_text("fov 0.001\n").camera.fov_degrees == 0.001);
}

TEST_CASE("resolution must be whole numbers from 1 to 65536", "[scene][camera][errors]") {
  require_error("resolution 0 300\n", 1, 12, "width must be a whole number from 1 to 65536");
  require_error("resolution 500 2.5\n", 1, 16, "height must be a whole number from 1 to 65536");
  require_error("resolution -5 300\n", 1, 12, "whole number from 1");
  require_error("resolution 1e10 300\n", 1, 12, "whole number");
}

TEST_CASE("samples must be a whole number from 1 to 65536", "[scene][camera][errors]") {
  require_error("samples 0\n", 1, 9, "whole number from 1 to 65536");
  require_error("samples 1.5\n", 1, 9, "whole number from 1");
}

TEST_CASE("maxdepth must be a whole number from 0 to 65536", "[scene][camera][errors]") {
  require_error("maxdepth -1\n", 1, 10, "whole number from 0 to 65536");
  require_error("maxdepth 0.5\n", 1, 10, "whole number from 0");
}

TEST_CASE("eye equal to lookat is an error at the later of the two commands",
          "[scene][camera][errors]") {
  require_error("eye 1 2 3\nsphere\nlookat 1 2 3\nplane\n", 3, 1,
                "eye and lookat are the same point");
  require_error("lookat 0 0 5\nsphere\n  eye 0 0 5\n", 3, 3, "same point");
  // The default lookat is the origin.
  require_error("sphere\neye 0 0 0\n", 2, 1, "same point");
}

TEST_CASE("eye and lookat too close to give a direction are an error that says so",
          "[scene][camera][errors]") {
  require_error("eye 0 0 0\nlookat 1e-200 0 0\n", 2, 1,
                "the view direction (lookat - eye) is degenerate: eye and lookat are only 1e-200 apart");
  require_error("lookat 0 0 1e-160\neye 0 0 0\nsphere\n", 2, 1, "degenerate");
  // Close but representable: a direction like any other.
  CHECK(load_text("eye 0 0 0\nlookat 1e-100 0 0\n").camera.lookat == Vec3{1e-100, 0, 0});
}

TEST_CASE("up parallel to the view direction is an error at the last camera command involved",
          "[scene][camera][errors]") {
  require_error("up 0 1 0\neye 0 5 0\n", 2, 1, "parallel");
  require_error("eye 0 5 0\nup 0 -3 0\nsphere\n", 2, 1, "parallel");
  require_error("eye 1 1 1\nup 1 1 1\nlookat -2 -2 -2\n", 3, 1, "parallel");
  // Only the default up is involved besides eye.
  require_error("eye 0 -5 0\n", 1, 1, "parallel");
  CHECK(load_text("eye 0 5 0.001\n").camera.eye == Vec3{0, 5, 0.001});
}

TEST_CASE("a zero-length up vector is an error at its first number", "[scene][camera][errors]") {
  require_error("up 0 0 0\n", 1, 4, "zero-length");
}

TEST_CASE("camera commands with the wrong number of arguments", "[scene][camera][errors]") {
  require_error("eye 1 2\n", 1, 8, "wrong number of arguments");
  require_error("eye 1 2 3 4\n", 1, 11, "wrong number of arguments");
  require_error("fov\n", 1, 4, "wrong number of arguments");
  require_error("fov 40 50\n", 1, 8, "wrong number of arguments");
  require_error("resolution 500\n", 1, 15, "wrong number of arguments");
  require_error("background 1 1 1 1\n", 1, 18, "wrong number of arguments");
  require_error("maxdepth\n", 1, 9, "wrong number of arguments");
  require_error("samples 4 4\n", 1, 11, "wrong number of arguments");
  require_error("lookat\n", 1, 7, "wrong number of arguments");
  require_error("up 0 1\n", 1, 7, "wrong number of arguments");
}

TEST_CASE("lens gives the thin lens's radius and focus distance, and without it the camera is "
          "a pinhole",
          "[scene][camera]") {
  const clrt::Scene pinhole = load_text("");
  CHECK(pinhole.camera.lens_radius == 0);
  CHECK(pinhole.camera.focus_distance == 1);
  const clrt::Scene s = load_text("LENS 0.25 7.5\n");
  CHECK(s.camera.lens_radius == 0.25);
  CHECK(s.camera.focus_distance == 7.5);
  CHECK(load_text("lens 1 2\nlens 0 3\n").camera.lens_radius == 0);
}

TEST_CASE("lens: a radius >= 0 and a focus distance > 0, two numbers", "[scene][camera][errors]") {
  require_error("lens -0.1 5\n", 1, 6, "the lens radius must be >= 0");
  require_error("lens 0.1 0\n", 1, 10, "the focus distance must be > 0");
  require_error("lens 0.1 -2\n", 1, 10, "the focus distance must be > 0");
  require_error("lens 0.1\n", 1, 9, "wrong number of arguments");
  require_error("lens 0.1 2 3\n", 1, 12, "wrong number of arguments");
}
