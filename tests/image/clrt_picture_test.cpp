// clrt's picture pipeline end to end: path mode's 8-bit outputs are sRGB-encoded, the Whitted
// modes' keep the contract's bytes, --exposure and --tonemap, their usage errors, and the note
// for a Whitted scene rendered in path mode. Each 8-bit file is checked against the PFM of the
// same render, encoded here with the formulas the docs state.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "image/image.hpp"
#include "image/image_info.hpp"
#include "run_tool.hpp"

using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

const std::string kCornell = quoted(CLRT_SOURCE_DIR "/scenes/cornell.ray");
const std::string kLightsPoint = quoted(CLRT_SOURCE_DIR "/scenes/lights-point.ray");
const std::string kTest2 = quoted(CLRT_SOURCE_DIR "/scenes/test2.ray");
const std::string kSmall = " --resolution 24x16 --spp 4";

ToolResult clrt_run(const ScratchDir& dir, const std::string& args) {
  return run_tool(dir, CLRT_EXE, args);
}

// The byte a linear value is written as, by the docs' formulas: 2^stops, the curve, sRGB's
// encoding when `srgb`, then clamp, times 255, round.
int expected_byte(float linear, double stops, bool filmic, bool srgb) {
  double v = static_cast<double>(linear) * std::pow(2.0, stops);
  if (!(v > 0)) return 0;
  if (filmic) v = v * (2.51 * v + 0.03) / (v * (2.43 * v + 0.59) + 0.14);
  v = std::min(v, 1.0);
  if (srgb) v = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
  return static_cast<int>(std::lround(std::min(v, 1.0) * 255));
}

// How many channels of `bytes` (RGBA) differ from `floats` (RGB) encoded as expected_byte says.
int mismatches(const clrt::Rgba8Image& bytes, const clrt::FloatImage& floats, double stops,
               bool filmic, bool srgb) {
  REQUIRE(bytes.width == floats.width);
  REQUIRE(bytes.height == floats.height);
  int wrong = 0;
  for (std::size_t i = 0; i < floats.rgb.size(); ++i)
    if (bytes.frames.at(0).at(i + i / 3) != expected_byte(floats.rgb[i], stops, filmic, srgb))
      ++wrong;
  return wrong;
}

// Renders `args` to out.pfm and to each 8-bit format, with `picture` options for the latter.
clrt::FloatImage render_all(const ScratchDir& dir, const std::string& args,
                            const std::string& picture = "") {
  REQUIRE(clrt_run(dir, args + " -q -o " + quoted(dir.file("out.pfm"))).status == 0);
  for (const char* name : {"out.png", "out.ppm", "out.fsf"})
    REQUIRE(clrt_run(dir, args + picture + " -q -o " + quoted(dir.file(name))).status == 0);
  return clrt::read_pfm(dir.file("out.pfm"));
}

}  // namespace

TEST_CASE("in path mode clrt's 8-bit outputs are the sRGB encoding of the render's floats",
          "[cli][picture]") {
  ScratchDir dir;
  const clrt::FloatImage floats = render_all(dir, kCornell + kSmall + " --mode path");
  for (const char* name : {"out.png", "out.ppm", "out.fsf"}) {
    INFO(name);
    const clrt::Rgba8Image bytes = clrt::read_image(dir.file(name));
    CHECK(mismatches(bytes, floats, 0, false, true) == 0);
    // The render has values the encoding moves: without it the bytes would differ.
    CHECK(mismatches(bytes, floats, 0, false, false) > 100);
  }
  const clrt::ImageInfo info = clrt::read_image_info(dir.file("out.png"));
  CHECK(std::find(info.details.begin(), info.details.end(),
                  std::pair<std::string, std::string>{"colour space", "sRGB"}) !=
        info.details.end());
}

TEST_CASE("in the Whitted modes clrt's 8-bit outputs keep the contract's quantisation",
          "[cli][picture]") {
  for (const char* mode : {"trace", "cast"}) {
    INFO(mode);
    ScratchDir dir;
    const clrt::FloatImage floats =
        render_all(dir, kLightsPoint + kSmall + " --mode " + std::string(mode));
    for (const char* name : {"out.png", "out.ppm", "out.fsf"}) {
      INFO(name);
      CHECK(clrt::read_image(dir.file(name)).frames == clrt::quantize(floats).frames);
    }
  }
}

TEST_CASE("exposure and the tone curve (--exposure, --tonemap) shape the 8-bit outputs of every mode", "[cli][picture]") {
  SECTION("path mode: exposure, filmic, sRGB") {
    ScratchDir dir;
    const clrt::FloatImage floats = render_all(dir, kCornell + kSmall + " --mode path",
                                               " --exposure 1.5 --tonemap filmic");
    for (const char* name : {"out.png", "out.ppm", "out.fsf"}) {
      INFO(name);
      CHECK(mismatches(clrt::read_image(dir.file(name)), floats, 1.5, true, true) == 0);
    }
  }
  SECTION("trace mode: exposure doubles, no sRGB") {
    ScratchDir dir;
    const clrt::FloatImage floats = render_all(dir, kLightsPoint + kSmall, " --exposure 1");
    const clrt::Rgba8Image png = clrt::read_image(dir.file("out.png"));
    CHECK(mismatches(png, floats, 1, false, false) == 0);
    CHECK(mismatches(png, floats, 0, false, false) > 100);
  }
  SECTION("a path-mode FSF animation's frames are the numbered PNGs' pictures") {
    ScratchDir dir;
    const std::string args = kCornell + " --resolution 12x8 --mode path --frames 2 -q -o ";
    REQUIRE(clrt_run(dir, args + quoted(dir.file("turn.fsf"))).status == 0);
    REQUIRE(clrt_run(dir, args + quoted(dir.file("turn.png"))).status == 0);
    const clrt::Rgba8Image fsf = clrt::read_fsf(dir.file("turn.fsf"));
    REQUIRE(fsf.frames.size() == 2);
    CHECK(fsf.frames[0] == clrt::read_png(dir.file("turn-0001.png")).frames[0]);
    CHECK(fsf.frames[1] == clrt::read_png(dir.file("turn-0002.png")).frames[0]);
  }
}

TEST_CASE("the picture options' usage errors", "[cli][picture]") {
  ScratchDir dir;
  const std::string scene = kTest2 + " --resolution 8x8 ";
  const ToolResult typo = clrt_run(dir, scene + "--tonemap filmc -o " + quoted(dir.file("a.png")));
  CHECK(typo.status == 2);
  CHECK_THAT(typo.err, Contains("--tonemap: filmc is not one of clamp, filmic (did you mean filmic?)"));
  CHECK(clrt_run(dir, scene + "--tonemap FILMIC -q -o " + quoted(dir.file("a.png"))).status == 0);
  const ToolResult exposure = clrt_run(dir, scene + "--exposure abc -o " + quoted(dir.file("a.png")));
  CHECK(exposure.status == 2);
  CHECK_THAT(exposure.err, Contains("--exposure: abc is not a number"));
  for (const char* asked : {"--exposure 1", "--tonemap filmic"}) {
    INFO(asked);
    const ToolResult floats =
        clrt_run(dir, scene + asked + " -o " + quoted(dir.file("a.exr")));
    CHECK(floats.status == 2);
    CHECK_THAT(floats.err, Contains("keeps the render's linear values"));
  }
  const ToolResult clamp = clrt_run(dir, scene + "--max-sample-value 0 -o none");
  CHECK(clamp.status == 2);
  CHECK_THAT(clamp.err, Contains("--max-sample-value: 0 is not above 0"));
  CHECK(clrt_run(dir, scene + "--max-sample-value 10 -q -o none").status == 0);
}

TEST_CASE("a Whitted scene in path mode gets one note that the image may be dark",
          "[cli][picture]") {
  ScratchDir dir;
  const std::string small = " --resolution 8x8 --spp 1 -o none";
  const ToolResult path = clrt_run(dir, kLightsPoint + small + " --mode path");
  CHECK(path.status == 0);
  CHECK_THAT(path.err, Contains("clrt: note: " + std::string(CLRT_SOURCE_DIR) +
                                "/scenes/lights-point.ray: in path mode ambient light is not "
                                "used and point and spot lights fall off with distance (1/d^2)"));
  CHECK_THAT(path.err, Contains("the image may be dark"));
  const std::size_t first = path.err.find("clrt: note:");
  CHECK(path.err.find("clrt: note:", first + 1) == std::string::npos);
  CHECK(clrt_run(dir, kLightsPoint + small + " --mode path -q").err.empty());
  CHECK_THAT(clrt_run(dir, kLightsPoint + small).err, !Contains("note:"));
  // An area light, or a background bright enough to light the scene: no note.
  CHECK_THAT(clrt_run(dir, kCornell + small + " --mode path").err, !Contains("note:"));
  CHECK_THAT(clrt_run(dir, kTest2 + small + " --mode path").err, !Contains("note:"));
}

TEST_CASE("a scene with objects and no light gets a note that they render black",
          "[cli][picture]") {
  ScratchDir dir;
  const std::string small = " --resolution 8x8 -o none";
  const std::string unlit = quoted(dir.write("unlit.ray", "sphere\n"));
  for (const char* mode : {"trace", "cast", "path"}) {
    INFO(mode);
    const ToolResult run = clrt_run(dir, unlit + small + " --mode " + mode);
    CHECK(run.status == 0);
    CHECK_THAT(run.err, Contains("unlit.ray: the scene has no light, so its objects render black"));
  }
  // Lit by a bright sky in path mode, by any light otherwise, or with nothing in it: no note.
  const std::string sky = quoted(dir.write("sky.ray", "background 1 1 1\nsphere\n"));
  CHECK_THAT(clrt_run(dir, sky + small + " --mode path").err, !Contains("note:"));
  CHECK_THAT(clrt_run(dir, sky + small).err, Contains("no light"));
  const std::string lit = quoted(dir.write("lit.ray", "light 1 1 1 ambient\nsphere\n"));
  CHECK_THAT(clrt_run(dir, lit + small).err, !Contains("note:"));
  const std::string empty = quoted(dir.write("empty.ray", "background 0 0 1\n"));
  CHECK_THAT(clrt_run(dir, empty + small).err, !Contains("note:"));
  // Glowing surfaces light a path-mode scene; the Whitted modes only show them.
  const std::string glow = quoted(dir.write("glow.ray", "emission 1 1 1\nsphere\n"));
  CHECK_THAT(clrt_run(dir, glow + small + " --mode path").err, !Contains("note:"));
  CHECK_THAT(clrt_run(dir, glow + small).err, Contains("only its glowing surfaces show"));
}
