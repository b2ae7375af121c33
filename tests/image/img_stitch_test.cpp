// clrt-img stitch end to end: tiles written to files stitch to the bytes of the full image.
#include <catch2/catch.hpp>
#include <string>

#include "image/image.hpp"
#include "run_tool.hpp"

using clrt::FloatImage;
using clrt::Placement;
using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

constexpr int kWidth = 37, kHeight = 23;  // not multiples of the tile size

// A synthetic render: smooth ramps, values above 1 and below 0, every sample different.
float value(int x, int y, int c) {
  return static_cast<float>(x) / 30.0f - 0.1f + static_cast<float>(y * y) / 400.0f +
         0.37f * static_cast<float>(c);
}

FloatImage region(int x0, int y0, int width, int height) {
  std::vector<float> rgb;
  for (int y = y0; y < y0 + height; ++y)
    for (int x = x0; x < x0 + width; ++x)
      for (int c = 0; c < 3; ++c) rgb.push_back(value(x, y, c));
  return FloatImage(width, height, rgb, Placement{x0, y0, kWidth, kHeight});
}

// Tiles of at most 16x8, written as `extension`; their paths, shell-quoted.
std::string write_tiles(const ScratchDir& dir, const std::string& extension,
                        const clrt::WriteOptions& options = {}) {
  std::string paths;
  for (int y = 0; y < kHeight; y += 8)
    for (int x = 0; x < kWidth; x += 16) {
      const std::string path =
          dir.file("tile-" + std::to_string(x) + "-" + std::to_string(y) + "." + extension);
      clrt::write_image(path, region(x, y, std::min(16, kWidth - x), std::min(8, kHeight - y)),
                        options);
      paths += " " + quoted(path);
    }
  return paths;
}

}  // namespace

TEST_CASE("stitched PNG tiles have the bytes of the full PNG", "[img][stitch]") {
  ScratchDir dir;
  const std::string full = dir.file("full.png"), out = dir.file("out.png");
  clrt::write_image(full, FloatImage(kWidth, kHeight, region(0, 0, kWidth, kHeight).rgb));
  const ToolResult result = run_img(dir, "stitch " + quoted(out) + write_tiles(dir, "png"));
  INFO(result.err);
  REQUIRE(result.status == 0);
  CHECK(read_bytes(out) == read_bytes(full));
  const ToolResult piped = run_img(dir, "stitch - --format png" + write_tiles(dir, "png"));
  CHECK(piped.out == read_bytes(full));
}

TEST_CASE("stitched EXR tiles have the bytes of the full EXR, half and float", "[img][stitch]") {
  for (const clrt::ExrPixel pixel : {clrt::ExrPixel::Half, clrt::ExrPixel::Float}) {
    ScratchDir dir;
    const std::string full = dir.file("full.exr"), out = dir.file("out.exr");
    clrt::write_image(full, FloatImage(kWidth, kHeight, region(0, 0, kWidth, kHeight).rgb),
                      {pixel});
    const ToolResult result = run_img(dir, "stitch " + quoted(out) + write_tiles(dir, "exr", {pixel}));
    INFO(result.err);
    REQUIRE(result.status == 0);
    CHECK(read_bytes(out) == read_bytes(full));
  }
}

TEST_CASE("stitch reports gaps and overlaps with the pixels, and refuses tiles without placement",
          "[img][stitch]") {
  ScratchDir dir;
  const std::string a = dir.file("a.png"), b = dir.file("b.png"), c = dir.file("c.png");
  clrt::write_image(a, region(0, 0, 20, kHeight));
  clrt::write_image(b, region(20, 0, 17, 10));
  clrt::write_image(c, region(18, 10, 19, 13));
  const std::string out = dir.file("out.png");
  ToolResult result = run_img(dir, "stitch " + quoted(out) + " " + quoted(a) + " " + quoted(b));
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains("clrt-img: error: the tiles leave 221 of the 37x23 frame's "
                                  "pixels uncovered: x [20, 37) y [10, 23)"));
  result = run_img(dir, "stitch " + quoted(out) + " " + quoted(a) + " " + quoted(b) + " " +
                            quoted(c));
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains("tiles " + a + " and " + c +
                                  " overlap: both cover pixels x [18, 20) y [10, 23)"));

  const std::string ppm = dir.file("a.ppm");
  clrt::write_image(ppm, region(0, 0, 20, kHeight));
  result = run_img(dir, "stitch " + quoted(out) + " " + quoted(ppm) + " " + quoted(b));
  CHECK(result.status == 2);
  CHECK_THAT(result.err, Contains("ppm cannot record where a tile belongs"));
  CHECK(run_img(dir, "stitch " + quoted(out)).status == 2);
  CHECK_FALSE(std::filesystem::exists(out));
}
