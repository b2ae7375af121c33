// Every malformed NFF construct is reported as FILE:LINE:COLUMN at the right place.
#include <catch2/catch.hpp>
#include <cmath>

#include "scene_test_support.hpp"

using clrt::test::load_error_of_file;
using clrt::test::ScratchDir;

namespace {

// Seven lines: the view.
const std::string kView = "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 0\nresolution 8 8\n";

void require_nff_error(const std::string& text, int line, int column, const std::string& part) {
  clrt::test::require_error(text, line, column, part, "scene.nff");
}

}  // namespace

TEST_CASE("NFF errors are FILE:LINE:COLUMN: error: MESSAGE", "[scene][nff][errors]") {
  ScratchDir dir;
  const std::string path = dir.write("bad.nff", kView + "s 0 0 0 1\n  sphere 0 0 0 1\n");
  const clrt::SceneError e = load_error_of_file(path);
  CHECK(std::string(e.what()) ==
        path + ":9:3: error: unknown entity 'sphere' (NFF has v, b, l, f, c, s, p and pp)");
}

TEST_CASE("NFF: an unknown entity, or numbers before any entity", "[scene][nff][errors]") {
  require_nff_error(kView + "tpp 3\n", 8, 1, "unknown entity 'tpp'");
  require_nff_error(kView + "\"s\" 0 0 0 1\n", 8, 1, "unknown entity 's'");
  require_nff_error("# numbers first\n  1 2 3\n" + kView, 2, 3,
                    "expected an entity (v, b, l, f, c, s, p or pp), found the number '1'");
}

TEST_CASE("NFF: a word that is not a number, on the entity's lines", "[scene][nff][errors]") {
  require_nff_error(kView + "s 0 0 abc 1\n", 8, 7, "expected a number, found 'abc'");
  require_nff_error(kView + "s 0 nan 0 1\n", 8, 5, "not a finite number");
  require_nff_error(kView + "p 3\n0 0 0\n1 0 1e999\n0 1 0\n", 10, 5, "out of the range");
  require_nff_error(kView + "b 0 0,5 0\n", 8, 5, "expected a number, found '0,5'");
}

// Too few: just past the entity's last word; too many: at the first extra one, on any line.
TEST_CASE("NFF: a wrong count of numbers", "[scene][nff][errors]") {
  require_nff_error(kView + "s 0 0 0\ns 1 1 1 1\n", 8, 8, "s takes 4 arguments, found 3");
  require_nff_error(kView + "b 0 0\n", 8, 6, "b takes 3 arguments, found 2");
  require_nff_error(kView + "l 1 2 3 4 5   # r g b?\n", 8, 12, "l takes 3 or 6 arguments, found 5");
  require_nff_error(kView + "f 1 1 1 1 0 0 0\n", 8, 16, "f takes 8 arguments, found 7");
  require_nff_error(kView + "c\n0 0 0 1\n0 0 1\n", 10, 6, "c takes 8 arguments, found 7");
  require_nff_error(kView + "s 0 0 0 1 2\n", 8, 11, "s takes 4 arguments, found 5");
  require_nff_error(kView + "s 0 0 0 1\n  5 6\n", 9, 3, "s takes 4 arguments, found 6");
  require_nff_error(kView + "l 1 2 3 1 1 1 1\n", 8, 15, "l takes 3 or 6 arguments, found 7");
}

TEST_CASE("NFF: p and pp take a vertex count >= 3 and that many vertices", "[scene][nff][errors]") {
  require_nff_error(kView + "p\n", 8, 2, "p needs its vertex count");
  require_nff_error(kView + "p 2\n0 0 0\n1 0 0\n", 8, 3,
                    "the vertex count must be a whole number from 3 to");
  require_nff_error(kView + "pp 3.5\n", 8, 4, "whole number from 3 to 1048576, found 3.5");
  require_nff_error(kView + "p 4\n0 0 0\n1 0 0\n1 1 0\n", 11, 6,
                    "p with 4 vertices (x y z each) takes 12 arguments after '4', found 9");
  require_nff_error(kView + "p 3\n0 0 0\n1 0 0\n1 1 0\n2 2 2\n", 12, 1,
                    "p with 3 vertices (x y z each) takes 9 arguments after '3', found 12");
  require_nff_error(kView + "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0\n", 11, 10,
                    "pp with 3 vertices (x y z nx ny nz each) takes 18 arguments after '3', "
                    "found 17");
  require_nff_error(kView + "pp 3\n0 0 0 0 0 1\n1 0 0  0 0 0\n0 1 0 0 0 1\n", 10, 8,
                    "a vertex normal must not be a zero-length vector");
}

TEST_CASE("NFF: a concave p or pp beyond the corner limit is refused at its vertex count",
          "[scene][nff][errors][polygons]") {
  // A star of 5000 corners: tips at radius 2, notches at radius 1.
  const int corners = 5000;
  std::string p = "p " + std::to_string(corners) + "\n", pp = "pp " + std::to_string(corners) + "\n";
  for (int i = 0; i < corners; ++i) {
    const double angle = 2 * 3.14159265358979 * i / corners, r = i % 2 ? 1 : 2;
    const std::string xyz = std::to_string(r * std::cos(angle)) + " " + std::to_string(r * std::sin(angle)) + " 0";
    p += xyz + "\n";
    pp += xyz + " 0 0 1\n";
  }
  const std::string expected = "a concave polygon of 5000 corners: clrt cuts concave polygons of at most 4096";
  require_nff_error(kView + p, 8, 3, expected);
  require_nff_error(kView + pp, 8, 4, expected);
}

TEST_CASE("NFF: f's numbers in their ranges", "[scene][nff][errors]") {
  require_nff_error(kView + "f 1 1 1 1 1.5 10 0 1\n", 8, 11,
                    "Ks (also the reflectivity) must be in [0, 1], found 1.5");
  require_nff_error(kView + "f 1 1 1 1 0 10 -0.1 1\n", 8, 16,
                    "T (the transmittance) must be in [0, 1], found -0.1");
  require_nff_error(kView + "f 1 1 1 1 0 -3 0 1\n", 8, 13,
                    "the Phong exponent (Shine) must be >= 0, found -3");
  require_nff_error(kView + "f 1 1 1 1 0 x 0 1\n", 8, 13, "expected a number, found 'x'");
}

TEST_CASE("NFF: a cone or cylinder needs an axis", "[scene][nff][errors]") {
  require_nff_error(kView + "c 1 2 3 0.5\n  1 2 3 0.5\n", 9, 3, "the apex is the base point");
}

TEST_CASE("NFF: a sphere or cone too large to place", "[scene][nff][errors]") {
  require_nff_error(kView + "s 0 0 0 1e-320\n", 8, 1, "cannot be inverted");
  require_nff_error(kView + "c 0 0 0 1 1e300 1e300 1e300 1\n", 8, 11, "'1e300' is too large");
}

TEST_CASE("NFF: the view is required, once, with its parts in order", "[scene][nff][errors]") {
  require_nff_error("s 0 0 0 1\n", 1, 1, "the file has no view (v)");
  require_nff_error("", 1, 1, "the file has no view (v)");
  require_nff_error(kView + "s 0 0 0 1\n\nv\n", 10, 1, "a second view (v): the first is at line 1");
  require_nff_error("v\nat 0 0 0\n", 2, 1, "the view (v) needs 'from' next, found 'at'");
  require_nff_error("v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\ns 0 0 0 1\n", 6, 1,
                    "the view (v) needs 'hither' next, found 's'");
  require_nff_error("v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0   \n", 4, 9,
                    "the file ends inside the view (v): 'angle' is missing");
  require_nff_error(kView + "angle 30\n", 8, 1, "'angle' belongs to a view");
  require_nff_error("v 0 0 5\n", 1, 3, "v takes 0 arguments, found 3");
}

TEST_CASE("NFF: the view's numbers in their ranges", "[scene][nff][errors]") {
  const auto view = [](const std::string& angle, const std::string& hither,
                       const std::string& resolution, const std::string& up = "0 1 0") {
    return "v\nfrom 0 0 5\nat 0 0 0\nup " + up + "\nangle " + angle + "\nhither " + hither +
           "\nresolution " + resolution + "\n";
  };
  require_nff_error(view("0", "0", "8 8"), 5, 7, "the angle must be > 0 and < 180 degrees");
  require_nff_error(view("1e-17", "0", "8 8"), 5, 7, "too narrow for the device's single precision");
  require_nff_error(view("180", "0", "8 8"), 5, 7, "found 180");
  require_nff_error(view("45", "-1", "8 8"), 6, 8, "hither must be >= 0, found -1");
  require_nff_error(view("45", "0", "0 8"), 7, 12, "the image width must be a whole number from 1 to 65536");
  require_nff_error(view("45", "0", "8 7.5"), 7, 14, "the image height must be a whole number");
  require_nff_error(view("45", "0", "8 8", "0 0 0"), 4, 4,
                    "the up vector must not be a zero-length vector");
  require_nff_error(view("45", "0", "8 8", "0 0 2"), 4, 1,
                    "the up vector is parallel to the view direction");
  require_nff_error("v\nfrom 1 1 1\nat 1 1 1\nup 0 1 0\nangle 45\nhither 0\nresolution 8 8\n", 3, 1,
                    "eye and lookat are the same point");
}
