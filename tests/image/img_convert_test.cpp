// clrt-img convert end to end (what clrt-fsfconv's tests checked, and the formats it lacked).
#include <catch2/catch.hpp>
#include <string>

#include "image/image.hpp"
#include "image/image_info.hpp"
#include "run_tool.hpp"

using clrt::FloatImage;
using clrt::Rgba8Image;
using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

// Opaque pixels with distinct channels: PNG and PPM keep them exactly.
const Rgba8Image kAnimation{3,
                            2,
                            {{10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 255,  //
                              1,  2,  3,  255, 4,  5,  6,  255, 7,  8,  9,  255},
                             {200, 201, 202, 255, 203, 204, 205, 255, 206, 207, 208, 255,  //
                              0,   0,   0,   255, 255, 255, 255, 255, 128, 64,  32,  255}}};

// What a render holds: unclamped floats, some beyond what 8 bits keep.
const FloatImage kRender{2, 2, {0.1f, 0.5f, 1.5f, -0.2f, 0.25f, 0.75f, 1e-3f, 0.9f, 3.0f, 0.0f,
                                0.2f, 0.4f}};

// clrt-img convert IN OUT, then `extra` options.
ToolResult convert(const ScratchDir& dir, const std::string& in, const std::string& out,
                   const std::string& extra = "") {
  return run_img(dir, "convert " + quoted(in) + " " + quoted(out) + extra);
}

}  // namespace

TEST_CASE("convert: FSF -> PNG -> FSF gives back the same file", "[img][convert]") {
  ScratchDir dir;
  const std::string fsf = dir.file("in.fsf"), png = dir.file("mid.png"), back = dir.file("b.fsf");
  const Rgba8Image still{3, 2, {kAnimation.frames[0]}};
  clrt::write_image(fsf, still);
  REQUIRE(convert(dir, fsf, png).status == 0);
  CHECK(clrt::read_png(png).frames == still.frames);
  REQUIRE(convert(dir, png, back).status == 0);
  CHECK(read_bytes(back) == read_bytes(fsf));
}

TEST_CASE("convert: PPM both ways, --frame picks a frame (from 1), FSF keeps every frame",
          "[img][convert]") {
  ScratchDir dir;
  const std::string anim = dir.file("anim.fsf"), ppm = dir.file("f2.ppm"), fsf = dir.file("f2.fsf");
  clrt::write_image(anim, kAnimation);
  REQUIRE(convert(dir, anim, ppm, " --frame 2").status == 0);
  REQUIRE(convert(dir, ppm, fsf).status == 0);
  const Rgba8Image back = clrt::read_fsf(fsf);
  CHECK(back.width == 3);
  CHECK(back.frames == std::vector<Bytes>{kAnimation.frames[1]});

  const std::string copy = dir.file("copy.fsf");
  REQUIRE(convert(dir, anim, copy).status == 0);
  CHECK(read_bytes(copy) == read_bytes(anim));
  const ToolResult one = convert(dir, anim, dir.file("x.png"));
  CHECK(one.status == 1);
  CHECK_THAT(one.err, Contains("holds 2 frames: pick one with --frame N (counted from 1)") &&
                         Contains("%04d"));
  const std::string first = dir.file("first.png");
  REQUIRE(convert(dir, anim, first, " --frame 1").status == 0);
  CHECK(clrt::read_png(first).frames == std::vector<Bytes>{kAnimation.frames[0]});
}

TEST_CASE("convert: a %04d or %d in the output's name writes every frame, numbered from 1",
          "[img][convert]") {
  ScratchDir dir;
  const std::string anim = dir.file("anim.fsf");
  clrt::write_image(anim, kAnimation);
  const auto frame = [](std::size_t k) { return std::vector<Bytes>{kAnimation.frames[k - 1]}; };
  REQUIRE(convert(dir, anim, dir.file("turn-%04d.png")).status == 0);
  CHECK(clrt::read_png(dir.file("turn-0001.png")).frames == frame(1));
  CHECK(clrt::read_png(dir.file("turn-0002.png")).frames == frame(2));
  // --frame with a pattern writes that frame alone, under its number; %% is a % sign.
  REQUIRE(convert(dir, anim, dir.file("f%%-%d.ppm"), " --frame 2").status == 0);
  CHECK(clrt::read_ppm(dir.file("f%-2.ppm")).frames == frame(2));
  // A still through a pattern is frame 1.
  REQUIRE(convert(dir, dir.file("turn-0002.png"), dir.file("still-%02d.fsf")).status == 0);
  CHECK(clrt::read_fsf(dir.file("still-01.fsf")).frames == frame(2));
  CHECK(dir.entries() == std::set<std::string>{"anim.fsf", "turn-0001.png", "turn-0002.png",
                                                "f%-2.ppm", "still-01.fsf", "stdout.bin",
                                                "stderr.txt"});

  // Any other use of % is refused before anything is read or written.
  for (const char* pattern : {"a-%s.png", "a-%5d.png", "a-%d-%d.png", "a-%%.png", "a-%0d.png",
                              "a-%011d.png", "a-%.png", "a%"}) {
    INFO(pattern);
    const ToolResult refused = convert(dir, anim, dir.file(pattern));
    CHECK(refused.status == 2);
    CHECK_THAT(refused.err, Contains("clrt-img: error: ") &&
                                Contains("a frame pattern takes one %d or %0Nd (e.g. %04d)"));
  }
  const ToolResult beyond = convert(dir, anim, dir.file("x-%d.png"), " --frame 3");
  CHECK(beyond.status == 1);
  CHECK_THAT(beyond.err, Contains("has no frame 3: it holds frames 1 to 2"));
  CHECK(dir.entries().size() == 7);
}

TEST_CASE("convert: PFM and EXR are read, and float to 8-bit quantises as clrt does",
          "[img][convert]") {
  ScratchDir dir;
  const std::string pfm = dir.file("r.pfm"), png = dir.file("r.png"), direct = dir.file("d.png");
  clrt::write_image(pfm, kRender);
  clrt::write_image(direct, kRender);
  REQUIRE(convert(dir, pfm, png).status == 0);
  CHECK(read_bytes(png) == read_bytes(direct));

  // PFM holds 32-bit floats, so EXR keeps them unless --exr-pixel half; PFM back is bit-exact.
  const std::string exr = dir.file("r.exr"), pfm_back = dir.file("back.pfm");
  REQUIRE(convert(dir, pfm, exr).status == 0);
  CHECK(clrt::read_exr(exr).rgb == kRender.rgb);
  REQUIRE(convert(dir, exr, pfm_back).status == 0);
  CHECK(read_bytes(pfm_back) == read_bytes(pfm));
  const std::string half = dir.file("h.exr"), half_direct = dir.file("hd.exr");
  REQUIRE(convert(dir, pfm, half, " --exr-pixel half").status == 0);
  clrt::write_image(half_direct, kRender);
  CHECK(read_bytes(half) == read_bytes(half_direct));

  // 8-bit into EXR is half by default and loses nothing.
  const std::string eight_exr = dir.file("e.exr"), eight_png = dir.file("e.png");
  REQUIRE(convert(dir, direct, eight_exr).status == 0);
  CHECK(clrt::read_image_info(eight_exr).samples == "16-bit float (half)");
  REQUIRE(convert(dir, eight_exr, eight_png).status == 0);
  CHECK(read_bytes(eight_png) == read_bytes(direct));
}

TEST_CASE("convert: --srgb, --exposure and --tonemap shape a float image's way into 8 bits",
          "[img][convert][display]") {
  ScratchDir dir;
  const std::string pfm = dir.file("r.pfm");
  clrt::write_image(pfm, kRender);
  // By hand: sRGB's 1.055 v^(1/2.4) - 0.055 (12.92 v up to 0.0031308), clamped, * 255, rounded.
  const std::vector<std::uint8_t> srgb{89, 188, 255, 255, 0, 137, 225, 255,
                                       3,  243, 255, 255, 0, 124, 170, 255};
  for (const char* name : {"s.png", "s.ppm", "s.fsf", "s.gif"}) {
    INFO(name);
    REQUIRE(convert(dir, pfm, dir.file(name), " --srgb").status == 0);
    if (std::string(name) != "s.gif") CHECK(clrt::read_image(dir.file(name)).frames[0] == srgb);
  }
  // Exposure doubles per stop: +1 reads 0.1 as 0.2 (51), 0.25 as 0.5 (128).
  REQUIRE(convert(dir, pfm, dir.file("e.png"), " --exposure 1").status == 0);
  const std::vector<std::uint8_t> doubled{51, 255, 255, 255, 0, 128, 255, 255,
                                          1,  255, 255, 255, 0, 102, 204, 255};
  CHECK(clrt::read_image(dir.file("e.png")).frames[0] == doubled);
  // Filmic: 0.5 -> 0.6163 (157), 1.5 -> 0.8768 (224).
  REQUIRE(convert(dir, pfm, dir.file("f.png"), " --tonemap filmic").status == 0);
  const clrt::Rgba8Image filmic = clrt::read_image(dir.file("f.png"));
  CHECK(filmic.frames[0][1] == 157);
  CHECK(filmic.frames[0][2] == 224);
  // Without them the conversion keeps the contract's bytes (the case above).
  REQUIRE(convert(dir, pfm, dir.file("plain.png"), " --tonemap clamp --exposure 0").status == 0);
  CHECK(clrt::read_image(dir.file("plain.png")).frames == clrt::quantize(kRender).frames);

  const ToolResult eight = convert(dir, dir.file("s.png"), dir.file("t.png"), " --srgb");
  CHECK(eight.status == 2);
  CHECK_THAT(eight.err, Contains("holds 8-bit values already"));
  const ToolResult floats = convert(dir, pfm, dir.file("t.exr"), " --exposure 2");
  CHECK(floats.status == 2);
  CHECK_THAT(floats.err, Contains("keeps the floats as they are"));
  const ToolResult typo = convert(dir, pfm, dir.file("t.png"), " --tonemap filmc");
  CHECK(typo.status == 2);
  CHECK_THAT(typo.err, Contains("(did you mean filmic?)"));
}

TEST_CASE("convert: into a half EXR, samples beyond the largest half are counted in a warning",
          "[img][convert]") {
  ScratchDir dir;
  const std::string pfm = dir.file("bright.pfm"), half = dir.file("h.exr");
  clrt::write_image(pfm, FloatImage(2, 1, {1e5f, 0.5f, 0.25f, 65504.0f, 2.0f, 7e4f}));
  const ToolResult result = convert(dir, pfm, half, " --exr-pixel half");
  REQUIRE(result.status == 0);
  CHECK(result.err == "clrt-img: warning: " + half +
                          ": 2 of the 6 samples are beyond 65504, the largest half float, and are "
                          "stored as infinity (--exr-pixel float keeps them)\n");
  const ToolResult kept = convert(dir, pfm, dir.file("f.exr"));
  REQUIRE(kept.status == 0);
  CHECK(kept.err.empty());
}

TEST_CASE("convert: a tile keeps its placement into PNG and EXR, with a warning elsewhere",
          "[img][convert][placement]") {
  ScratchDir dir;
  const std::string png = dir.file("t.png"), exr = dir.file("t.exr"), ppm = dir.file("t.ppm");
  clrt::write_image(png, FloatImage(2, 2, kRender.rgb, clrt::Placement{3, 1, 8, 4}));
  REQUIRE(convert(dir, png, exr).status == 0);
  CHECK(clrt::read_exr(exr).placement == clrt::Placement{3, 1, 8, 4});
  const ToolResult dropped = convert(dir, exr, ppm);
  CHECK(dropped.status == 0);
  CHECK_THAT(dropped.err, Contains("clrt-img: warning: ") && Contains("ppm cannot record"));
  CHECK(clrt::read_ppm(ppm).frames == clrt::read_png(png).frames);
}

TEST_CASE("convert: - writes to standard output in the format --format names", "[img][convert]") {
  ScratchDir dir;
  const std::string png = dir.file("a.png"), ppm = dir.file("a.ppm"), exr = dir.file("a.exr");
  clrt::write_image(png, kRender);
  clrt::write_image(ppm, kRender);
  clrt::write_image(exr, clrt::read_png(png));  // the 8-bit values, as half floats
  ToolResult piped = run_img(dir, "convert " + quoted(png) + " - --format ppm");
  CHECK(piped.status == 0);
  CHECK(piped.out == read_bytes(ppm));
  piped = run_img(dir, "convert " + quoted(png) + " - --format EXR");
  CHECK(piped.status == 0);
  CHECK(piped.out == read_bytes(exr));
  const ToolResult missing = run_img(dir, "convert " + quoted(png) + " -");
  CHECK(missing.status == 2);
  CHECK_THAT(missing.err, Contains("clrt-img: error: ") && Contains("format"));
  CHECK(missing.out.empty());
}

TEST_CASE("convert fails with status 1 on bad files and 2 on bad usage", "[img][convert]") {
  ScratchDir dir;
  const std::string anim = dir.file("anim.fsf"), missing = dir.file("missing.fsf"),
                    out = dir.file("out.png");
  clrt::write_image(anim, kAnimation);

  ToolResult result = convert(dir, missing, out);
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains("clrt-img: error: ") && Contains(missing));
  result = convert(dir, anim, out, " --frame 3");
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains("no frame 3"));
  result = convert(dir, anim, out, " --frame 0");
  CHECK(result.status == 2);
  CHECK_THAT(result.err, Contains("clrt-img: error: --frame: frames are counted from 1"));
  result = convert(dir, anim, out, " --frame two");
  CHECK(result.status == 2);
  CHECK_THAT(result.err, Contains("clrt-img: error: --frame: two is not a whole number"));
  result = convert(dir, anim, dir.file("out.tga"));
  CHECK(result.status == 2);
  CHECK_THAT(result.err, Contains("clrt-img: error: ") && Contains(".tga"));
  result = convert(dir, anim, out, " --format exr");
  CHECK(result.status == 2);
  CHECK_THAT(result.err, Contains("names png"));

  for (const std::string& args :
       std::vector<std::string>{"", "convert", "convert " + quoted(anim),
        "convert " + quoted(anim) + " " + quoted(out) + " --frame -1",
        "convert " + quoted(anim) + " " + quoted(out) + " --format gif",
        "convert " + quoted(anim) + " " + quoted(out) + " --exr-pixel double", "--bogus",
        "bogus"}) {
    INFO(args);
    result = run_img(dir, args);
    CHECK(result.status == 2);
    CHECK_THAT(result.err, Contains("clrt-img: error: "));
  }
  CHECK(dir.entries() == std::set<std::string>{"anim.fsf", "stdout.bin", "stderr.txt"});
}

TEST_CASE("clrt-img --version and --help", "[img]") {
  ScratchDir dir;
  ToolResult result = run_img(dir, "--version");
  CHECK(result.status == 0);
  CHECK(result.out_text().rfind("clrt-img, from clrt 0.1.0 (commit ", 0) == 0);
  result = run_img(dir, "--help");
  CHECK(result.status == 0);
  for (const char* command : {"convert", "info", "diff", "stitch"})
    CHECK_THAT(result.out_text(), Contains(command));
  result = run_img(dir, "stitch --help");
  CHECK(result.status == 0);
  CHECK_THAT(result.out_text(), Contains("tiles"));
}
