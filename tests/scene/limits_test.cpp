// Every limit of a scene is checked while loading, in 64 bits, with an error that names the real
// cause (each case here was once accepted, crashed or ran away).
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "scene/limits.hpp"
#include "scene_test_support.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

std::string area_light(long long samples) {
  return "light 1 1 1 area -1 3 -1 2 0 0 0 0 2 " + std::to_string(samples) + "\n";
}

}  // namespace

TEST_CASE("area-light samples are capped per light", "[scene][limits]") {
  // Two of these summed to 2^32 in 32 bits, and the shade kernel wrote past its buffer.
  require_error(area_light(2147483647), 1, 38, "light samples must be a whole number from 1 to 65536");
  require_error(area_light(65537), 1, 38, "from 1 to 65536");
  CHECK(load_text(area_light(65536)).lights.at(0).samples == 65536);
}

TEST_CASE("the lights' shadow samples per shading point are capped in sum", "[scene][limits]") {
  std::string text;
  for (int i = 0; i < 16; ++i) text += area_light(65536);  // exactly 2^20
  CHECK(load_text(text).lights.size() == 16);
  require_error(text + "light 1 1 1 point 0 3 0\n", 17, 1,
                "the lights so far take 1048577 shadow-ray samples per shading point, more than "
                "the limit of 1048576");
}

TEST_CASE("image sides and pixel count are capped", "[scene][limits]") {
  require_error("resolution 65536 65537\n", 1, 18, "height must be a whole number from 1 to 65536");
  require_error("resolution 65536 65536\n", 1, 12,
                "would have 4294967296 pixels, more than the limit of 268435456");
  const Scene s = load_text("resolution 16384 16384\n");
  CHECK(std::int64_t{s.width} * s.height == limits::kMaxPixels);
}

TEST_CASE("maxdepth and samples take the command line's caps", "[scene][limits]") {
  require_error("maxdepth 2000000000\n", 1, 10, "maxdepth must be a whole number from 0 to 65536");
  CHECK(load_text("maxdepth 65536\n").max_depth == 65536);
  require_error("samples 2147483647\n", 1, 9, "from 1 to 65536");
  CHECK(load_text("samples 65536\n").samples == 65536);
}

TEST_CASE("numbers beyond 1e12 are errors that say so", "[scene][limits]") {
  require_error("sphere 0 0 0 1e13\n", 1, 14, "'1e13' is too large: numbers in a scene lie within -1e12 and 1e12");
  // The BVH split once took a NaN bin from a sphere this large.
  require_error("scale 9e125 9e125 9e125\nsphere\n", 1, 7, "too large");
  require_error("light 1e300 1 1 ambient\n", 1, 7, "too large");
}

TEST_CASE("coordinates whose products would overflow single precision are errors",
          "[scene][limits]") {
  SECTION("an object reaching beyond 1e12 in world space") {
    require_error("scale 1e7 1e7 1e7\nscale 1e7 1e7 1e7\n  sphere\n", 3, 3,
                  "this object reaches 1e14 in world space, beyond the limit of 1e12");
  }
  SECTION("a mesh placed beyond it") {
    ScratchDir dir;
    dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1e6 0\nf 1 2 3\n");
    const SceneError e = load_error_of_file(dir.write("s.ray", "scale 1e7 1 1\nmesh t.obj\nscale 1 1e7 1\nmesh t.obj\n"));
    CHECK(e.where().line == 4);
    CHECK_THAT(e.message(), Catch::Contains("reaches 1e13 in world space"));
  }
  SECTION("a triangle beyond it") {
    CHECK(load_text("scale 1e6 1 1\ntriangle 0 0 0 1e6 0 0 0 1 0\n").triangles.size() == 1);
    require_error("scale 1e6 1 1\ntriangle 0 0 0 2e6 0 0 0 1 0\n", 2, 1,
                  "a coordinate reaches 2e12 in world space");
  }
  SECTION("an object too small for the scene around it") {
    require_error("eye 0 0 1e6\nscale 1e-7 1e-7 1e-7\ncube\n", 3, 1,
                  "in its own coordinates (where the device intersects it), the scene reaches 1e13");
  }
  SECTION("the limit itself is accepted") {
    CHECK(load_text("eye 0 0 1e12\nscale 1e12 1e12 1e12\nsphere\nreset\ncube\n").instances.size() == 2);
  }
}

TEST_CASE("a scene that is not a regular file is refused before it is read", "[scene][limits]") {
  SECTION("/dev/zero, which would be read until memory runs out") {
    const SceneError e = load_error_of_file("/dev/zero");
    CHECK(e.where().line == 0);
    CHECK_THAT(e.message(), Catch::Contains("cannot read the scene file (it is not a regular file)"));
  }
  SECTION("a FIFO, whose open would wait for a writer") {
    ScratchDir dir;
    REQUIRE(::mkfifo(dir.file("pipe.ray").c_str(), 0600) == 0);
    CHECK_THAT(load_error_of_file(dir.file("pipe.ray")).message(),
               Catch::Contains("it is not a regular file"));
  }
}

TEST_CASE("a scene file over the size limit is refused without reading it", "[scene][limits]") {
  ScratchDir dir;
  const std::string path = dir.write("huge.ray", "sphere\n");
  // Sparse: the size is there, the disk blocks are not.
  REQUIRE(::truncate(path.c_str(), static_cast<off_t>(limits::kMaxSceneFileBytes + 1)) == 0);
  CHECK_THAT(load_error_of_file(path).message(),
             Catch::Contains("it is 268435457 bytes, more than the limit of 256 MiB"));
}

TEST_CASE("a mesh file over the size limit is refused at its command, in the documented unit",
          "[scene][limits]") {
  ScratchDir dir;
  const std::string mesh = dir.write("huge.obj", "v 0 0 0\n");
  REQUIRE(::truncate(mesh.c_str(), static_cast<off_t>(limits::kMaxMeshFileBytes + 1)) == 0);
  const SceneError e = load_error_of_file(dir.write("s.ray", "sphere\nmesh huge.obj\n"));
  CHECK(e.where().line == 2);
  CHECK_THAT(e.message(), Catch::Contains("it is 2146435073 bytes, more than the limit of 2047 MiB"));
}

TEST_CASE("a mesh that is not a regular file is refused at its command", "[scene][limits]") {
  ScratchDir dir;
  const SceneError e = load_error_of_file(dir.write("s.ray", "sphere\nmesh /dev/zero\n"));
  CHECK(e.where().line == 2);
  CHECK_THAT(e.message(), Catch::Contains("bad mesh file /dev/zero: cannot be read (it is not a regular file)"));
}

TEST_CASE("a line over the length limit is an error quoting only its start", "[scene][limits]") {
  const std::string word(100000, 'x');
  const SceneError e = load_error("sphere\n" + word + "\n");
  CHECK(e.where().line == 2);
  CHECK(e.where().column == 65537);
  CHECK_THAT(e.message(), Catch::Contains("the line is 100000 bytes long, more than the limit of 65536"));
  CHECK(std::string(e.what()).size() < 300);
}

TEST_CASE("long words are quoted in errors by an excerpt", "[scene][limits]") {
  const std::string word(5000, '7');
  const SceneError not_number = load_error("sphere 0 0 0 " + word + "x\n");
  CHECK_THAT(not_number.message(), Catch::Contains("'" + std::string(40, '7') + "... (5001 bytes)'"));
  CHECK(not_number.message().size() < 200);
  const SceneError unknown = load_error(word + "\n");
  CHECK(unknown.message().size() < 200);
}
