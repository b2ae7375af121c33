// clrt-img diff end to end: the report, the exit status, the difference image.
#include <catch2/catch.hpp>
#include <string>

#include "image/image.hpp"
#include "run_tool.hpp"

using clrt::FloatImage;
using clrt::Rgba8Image;
using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

const Rgba8Image kA(2, 1, {{10, 20, 30, 255, 100, 100, 100, 255}});
const Rgba8Image kB(2, 1, {{10, 22, 30, 255, 100, 100, 95, 255}});

// A two-frame animation of kA then kB, written into `dir`.
std::string write_animation(const ScratchDir& dir) {
  const std::string anim = dir.file("anim.fsf");
  clrt::write_image(anim, Rgba8Image(2, 1, {kA.frames[0], kB.frames[0]}));
  return anim;
}

// clrt-img diff A B, then `extra` options.
ToolResult diff(const ScratchDir& dir, const std::string& a, const std::string& b,
                const std::string& extra) {
  return run_img(dir, "diff " + quoted(a) + " " + quoted(b) + " " + extra);
}

}  // namespace

TEST_CASE("diff of 8-bit images reports steps of 1/255 and exits 1 above the threshold",
          "[img][diff]") {
  ScratchDir dir;
  const std::string a = dir.file("a.png"), b = dir.file("b.ppm"), out = dir.file("d.png");
  clrt::write_image(a, kA);
  clrt::write_image(b, kB);
  ToolResult result =
      run_img(dir, "diff " + quoted(a) + " " + quoted(b) + " --out " + quoted(out));
  CHECK(result.status == 1);
  CHECK(result.out_text() ==
        "compared: R, G, B as 8-bit samples (differences in steps of 1/255)\npixels: 2\n"
        "differing pixels: 2 (a channel differs by more than 0)\n"
        "largest difference: 5 (of 255)\nPSNR: 41.2883361 dB\n");
  // |A - B| scaled by 1/5: green 2/5 of pixel 0, blue 1 of pixel 1.
  CHECK(clrt::read_png(out).frames == std::vector<Bytes>{{0, 102, 0, 255, 0, 0, 255, 255}});

  result = run_img(dir, "diff " + quoted(a) + " " + quoted(b) + " --threshold 2");
  CHECK(result.status == 1);
  CHECK_THAT(result.out_text(),
             Contains("differing pixels: 1 (a channel differs by more than 2)"));
  result = run_img(dir, "diff " + quoted(a) + " " + quoted(b) + " --threshold 5");
  CHECK(result.status == 0);
  result = run_img(dir, "diff " + quoted(a) + " " + quoted(a));
  CHECK(result.status == 0);
  CHECK_THAT(result.out_text(), Contains("largest difference: 0 (of 255)\nPSNR: inf dB\n"));
}

TEST_CASE("diff of two float images compares floats, a float against 8-bit quantises",
          "[img][diff]") {
  ScratchDir dir;
  const std::string a = dir.file("a.pfm"), b = dir.file("b.exr"), png = dir.file("a.png");
  clrt::write_image(a, FloatImage(2, 1, {0, 0, 0, 1, 0.5f, 3}));
  clrt::write_image(b, FloatImage(2, 1, {0, 0, 0.001f, 1, 0.5f, 3}), {clrt::ExrPixel::Float});
  clrt::write_image(png, FloatImage(2, 1, {0, 0, 0, 1, 0.5f, 3}));
  ToolResult result = run_img(dir, "diff " + quoted(a) + " " + quoted(b));
  CHECK(result.status == 1);
  CHECK(result.out_text() ==
        "compared: R, G, B as floats (differences in linear units)\npixels: 2\n"
        "differing pixels: 1 (a channel differs by more than 0)\n"
        "largest difference: 0.00100000005\nPSNR: 67.7815121 dB\n");
  CHECK(run_img(dir, "diff " + quoted(a) + " " + quoted(b) + " --threshold 0.0011").status == 0);
  result = run_img(dir, "diff " + quoted(a) + " " + quoted(png));
  CHECK(result.status == 0);
  CHECK_THAT(result.out_text(), Contains("as 8-bit samples") && Contains("PSNR: inf dB"));
}

TEST_CASE("diff refuses different sizes (1), animations without --frame (1) and bad options (2)",
          "[img][diff]") {
  ScratchDir dir;
  const std::string a = dir.file("a.png"), small = dir.file("s.png"), anim = write_animation(dir);
  clrt::write_image(a, kA);
  clrt::write_image(small, Rgba8Image(1, 1, {{1, 2, 3, 255}}));
  ToolResult result = run_img(dir, "diff " + quoted(a) + " " + quoted(small));
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains("2x1") && Contains("1x1"));
  result = diff(dir, a, anim, "");
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains("holds 2 frames: pick one with --frame-b N"));
  CHECK(diff(dir, a, anim, "--frame 1").status == 0);
  // --frame names both sides: the still has no frame 2.
  result = diff(dir, a, anim, "--frame 2");
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains(a + " has no frame 2: it holds one frame"));
  CHECK(diff(dir, a, anim, "--frame 0").status == 2);
  for (const char* threshold : {"-1", "nan", "inf", "x", "1e999"}) {
    INFO(threshold);
    result = run_img(dir, "diff " + quoted(a) + " " + quoted(a) + " --threshold " + threshold);
    CHECK(result.status == 2);
    CHECK_THAT(result.err, Contains("clrt-img: error: "));
  }
  CHECK(run_img(dir, "diff " + quoted(a) + " " + quoted(a) + " --out d.gif").status == 2);
  CHECK(run_img(dir, "diff " + quoted(a)).status == 2);
}

TEST_CASE("diff names each side's frame: --frame-a, --frame-b, or --frame for both",
          "[img][diff]") {
  ScratchDir dir;
  const std::string a = dir.file("a.png"), b = dir.file("b.png"), anim = write_animation(dir);
  clrt::write_image(a, kA);
  clrt::write_image(b, kB);
  CHECK(diff(dir, anim, b, "--frame-a 2").status == 0);
  CHECK(diff(dir, anim, b, "--frame-a 1").status == 1);
  CHECK(diff(dir, a, anim, "--frame-b 1").status == 0);
  ToolResult result = diff(dir, a, anim, "--frame-b 2");
  CHECK(result.status == 1);
  CHECK_THAT(result.out_text(), Contains("differing pixels: 2"));
  CHECK(diff(dir, anim, anim, "--frame 2").status == 0);
  CHECK(diff(dir, anim, anim, "--frame-a 1 --frame-b 2").status == 1);
  result = diff(dir, anim, anim, "--frame 1 --frame-b 2");
  CHECK(result.status == 2);
  CHECK_THAT(result.err, Contains("clrt-img: error: --frame excludes --frame-b"));
}
