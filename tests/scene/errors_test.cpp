#include <catch2/catch.hpp>

#include "scene_test_support.hpp"

using clrt::test::load_error;
using clrt::test::load_error_of_file;
using clrt::test::require_error;
using clrt::test::ScratchDir;

TEST_CASE("the error text is FILE:LINE:COLUMN: error: MESSAGE", "[scene][errors]") {
  ScratchDir dir;
  const std::string path = dir.write("bad.ray", "sphere\n  frobnicate 1 2\n");
  const clrt::SceneError e = load_error_of_file(path);
  CHECK(std::string(e.what()) == path + ":2:3: error: unknown command 'frobnicate'");
  CHECK(e.where().file == path);
}

TEST_CASE("an unknown command is reported at the command word", "[scene][errors]") {
  require_error("# comment\n\n\tspheres\n", 3, 2, "unknown command 'spheres'");
  require_error("eye 0 0 5\n1 2 3\n", 2, 1, "unknown command '1'");
  require_error("\"sphere\"\n", 1, 1, "unknown command 'sphere'");
}

TEST_CASE("a mistyped command or light kind gets the one it was probably meant to be",
          "[scene][errors]") {
  require_error("sphree\n", 1, 1, "unknown command 'sphree' (did you mean 'sphere'?)");
  require_error("LOOKAT 0 0 0\nmaterail 1 0 0 .2 .8 0 1 0 0\n", 2, 1,
                "unknown command 'materail' (did you mean 'material'?)");
  require_error("trnaslate 1 0 0\n", 1, 1, "(did you mean 'translate'?)");
  // Nothing close: no guess.
  const clrt::SceneError far = load_error("teapot\n");
  CHECK(far.message() == "unknown command 'teapot'");
  require_error("light 1 1 1 poitn 0 0 0\n", 1, 13,
                "unknown light kind 'poitn' (did you mean 'point'? expected ambient, point, "
                "directional, spot or area)");
  CHECK(load_error("light 1 1 1 strobe 0 0 0\n").message().find("did you mean") ==
        std::string::npos);
}

TEST_CASE("another renderer's scene or a mesh given as the scene is named for what it is",
          "[scene][errors]") {
  ScratchDir dir;
  const struct {
    const char* file;
    const char* what;
  } cases[] = {{"teapot.pbrt", "this is a pbrt scene"},   {"box.gltf", "this is a glTF scene"},
               {"box.GLB", "this is a glTF scene"},       {"cbox.xml", "this is a Mitsuba scene"},
               {"chess.pov", "this is a POV-Ray scene"},  {"bunny.ply", "this is a PLY mesh"}};
  for (const auto& c : cases) {
    INFO(c.file);
    const std::string path = dir.write(c.file, "Shape \"sphere\"\n");
    const clrt::SceneError e = load_error_of_file(path);
    CHECK(std::string(e.what()).rfind(path + ": error: " + c.what, 0) == 0);
    CHECK_THAT(e.message(), Catch::Contains("clrt reads .ray scenes (docs/scene-format.md) and NFF"));
  }
  const std::string obj = dir.write("cube.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CHECK_THAT(load_error_of_file(obj).message(),
             Catch::Contains("this is an OBJ mesh, not a scene clrt reads") &&
                 Catch::Contains("with `mesh \"cube.obj\"`"));
}

TEST_CASE("a word that is not a number is reported at that word", "[scene][errors]") {
  require_error("translate 1 two 3\n", 1, 13, "expected a number, found 'two'");
  require_error("fov 45deg\n", 1, 5, "expected a number");
  // Narrower, the focal length's square overflows the device's floats and every ray is NaN.
  require_error("fov 1e-17\n", 1, 5, "too narrow for the device's single precision");
  CHECK(clrt::test::load_text("fov 1e-9\n").camera.fov_degrees == 1e-9);
  require_error("fov 4,5\n", 1, 5, "expected a number");
  require_error("fov 0x10\n", 1, 5, "expected a number");
  require_error("fov \"45\"\n", 1, 5, "expected a number");
}

TEST_CASE("NaN, infinities and overflowing literals are rejected at their word",
          "[scene][errors]") {
  require_error("translate 0 nan 0\n", 1, 13, "not a finite number");
  require_error("background 0 0 -Inf\n", 1, 16, "not a finite number");
  require_error("scale 1 1 infinity\n", 1, 11, "not a finite number");
  require_error("eye 1e999 0 0\n", 1, 5, "out of the range");
}

TEST_CASE("too many arguments: the error points at the first extra word", "[scene][errors]") {
  require_error("reset now\n", 1, 7, "wrong number of arguments");
  require_error("translate 1 2 3   4 5\n", 1, 19, "translate takes 3 arguments, found 5");
  require_error("plane 1\n", 1, 7, "plane takes 0 arguments, found 1");
}

TEST_CASE("too few arguments: the error points just past the last word", "[scene][errors]") {
  require_error("translate 1 2   # missing z\n", 1, 14, "translate takes 3 arguments, found 2");
  require_error("scale\t2 2\r\n", 1, 10, "wrong number of arguments");
}

TEST_CASE("a scene file that cannot be read is reported without a line", "[scene][errors]") {
  ScratchDir dir;
  const std::string missing = dir.file("no-such-scene.ray");
  const clrt::SceneError e = load_error_of_file(missing);
  CHECK(e.where().file == missing);
  CHECK(e.where().line == 0);
  CHECK(std::string(e.what()) ==
        missing + ": error: cannot read the scene file (No such file or directory)");

  const clrt::SceneError folder_error = load_error_of_file(dir.path().string());
  CHECK(folder_error.where().line == 0);
  CHECK_THAT(folder_error.message(), Catch::Contains("folder"));
}

TEST_CASE("the first error in the file is the one reported", "[scene][errors]") {
  const clrt::SceneError e = load_error("sphere\nfov 200\nbogus\n");
  CHECK(e.where().line == 2);
}

TEST_CASE("a UTF-8 byte order mark at the start of a scene file is skipped", "[scene][errors]") {
  const std::string mark = "\xEF\xBB\xBF";
  CHECK(clrt::test::load_text(mark + "sphere 0 0 0 1\n").instances.size() == 1);
  CHECK(clrt::test::load_text(mark + "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 0\n"
                                     "resolution 8 8\ns 0 0 0 1\n",
                              "scene.nff")
            .instances.size() == 1);
  // Columns count from the first character after it, as an editor shows them.
  const clrt::SceneError e = load_error(mark + "sphre 0 0 0 1\n");
  CHECK(e.message() == "unknown command 'sphre' (did you mean 'sphere'?)");
  CHECK(e.where().column == 1);
  // Elsewhere it is no mark but bytes of a word.
  require_error("sphere\n" + mark + "sphere\n", 2, 1, "unknown command '" + mark + "sphere'");
}

TEST_CASE("a file that is no text is refused before it is read as a scene", "[scene][errors]") {
  const std::string png = std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16) + "\"";
  CHECK(std::string(load_error(png, "r.png").what()).find(": error: this is a PNG image, not a scene") !=
        std::string::npos);
  CHECK(load_error(png, "r.png").where().line == 0);
  CHECK(load_error(std::string("\x76\x2f\x31\x01\x02", 5)).message() ==
        "this is an OpenEXR image, not a scene");
  CHECK(load_error(std::string("\x3f\x02\0\0\x10\0\0\0", 8)).message() ==
        "this is an FSF image, not a scene");
  CHECK(load_error("\x1f\x8b\x08").message() == "this is a gzip archive, not a scene");
  require_error(std::string("sphere\neye 0\0 0 5\n", 18), 2, 6,
                "a NUL byte, which is not UTF-8 text: this is not a scene file");
  require_error("# caf\xe9\nsphere\n", 1, 6, "the byte 0xe9, which is not UTF-8 text");
  require_error("sphere\n\xc0\xaf\n", 2, 1, "the byte 0xc0");  // an overlong '/'
  require_error("sphere # \xe2\x82\n", 1, 10, "the byte 0xe2");  // cut short at the line's end
}

TEST_CASE("UTF-8 text beyond ASCII is a scene's text", "[scene][errors]") {
  CHECK(clrt::test::load_text("# caf\xc3\xa9, \xe2\x82\xac, \xf0\x9f\x8e\xa5\nsphere\n").instances.size() == 1);
}
