// A region of the image (--pixel-bounds, --crop-window) holds exactly the bits of the same
// pixels of the full render: on every scene in scenes/, with several samples and a seed, waves
// split small, both integrators, regions of one pixel, one row, one column, the image's edges
// and its interior. A region outside the image, empty or inverted is a usage error.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/region_options.hpp"
#include "render/integrator.hpp"
#include "render/usage_error.hpp"
#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

constexpr std::uint32_t kWidth = 23, kHeight = 17;

const std::vector<PixelRect> kRegions = {
    {0, 0, 1, 1},                      // the top-left pixel
    {kWidth - 1, kHeight - 1, 1, 1},   // the bottom-right pixel
    {11, 8, 1, 1},                     // one pixel inside
    {0, 5, kWidth, 1},                 // one row
    {7, 0, 1, kHeight},                // one column
    {kWidth - 1, 0, 1, kHeight},       // the right edge
    {0, kHeight - 1, kWidth, 1},       // the bottom edge
    {3, 2, 9, 11},                     // an interior rectangle (the megakernel's too)
    {0, 0, kWidth, kHeight},           // the whole image as a region
};

// The region's pixels cut out of a full image.
std::vector<float> cut(const FloatImage& full, const PixelRect& r) {
  std::vector<float> out;
  for (std::uint32_t y = r.y; y < r.y + r.height; ++y) {
    const auto row = full.rgb.begin() + 3 * (std::ptrdiff_t{y} * full.width + r.x);
    out.insert(out.end(), row, row + 3 * std::ptrdiff_t{r.width});
  }
  return out;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(float) * a.size()) == 0;
}

void settings(RenderOptions& o) {
  o.width = kWidth;
  o.height = kHeight;
  o.samples = 2;
  o.seed = 3;
}

}  // namespace

TEST_CASE("every region of every repository scene has the full render's bits", "[regions]") {
  for (const std::string& path : repository_scenes()) {
    const FloatImage full = render_file(path, settings);
    for (const PixelRect& region : kRegions) {
      // The megakernel shares the wavefront's bits (test_integrators.cpp): one region suffices.
      std::vector<std::string> integrators = {"wavefront"};
      if (region.width == 9) integrators.push_back("megakernel");
      for (const std::string& integrator : integrators) {
        INFO(path << ", region " << describe(region) << ", " << integrator_entry(integrator).name);
        const FloatImage part = render_file(path, [&](RenderOptions& o) {
          settings(o);
          o.region = region;
          o.integrator = integrator;
          o.wavefront = 1024;
        });
        CHECK(part.width == static_cast<int>(region.width));
        CHECK(part.height == static_cast<int>(region.height));
        CHECK(same_bits(part.rgb, cut(full, region)));
      }
    }
  }
}

TEST_CASE("crop windows map to pixels as pbrt maps them", "[regions]") {
  RegionRequest crop;
  crop.crop_window = std::array<double, 4>{0.25, 0.5, 0.1, 1.0};
  const std::optional<PixelRect> r = resolve_region(crop, 10, 20);
  REQUIRE(r);
  CHECK(r->x == 3);      // ceil(2.5)
  CHECK(r->width == 2);  // ceil(5) - 3
  CHECK(r->y == 2);      // ceil(2)
  CHECK(r->height == 18);
  CHECK_FALSE(resolve_region(RegionRequest{}, 10, 20));
}

TEST_CASE("regions outside the image, empty or inverted are usage errors", "[regions]") {
  const auto bounds = [](double x0, double x1, double y0, double y1) {
    RegionRequest r;
    r.pixel_bounds = std::array<double, 4>{x0, x1, y0, y1};
    return r;
  };
  CHECK_THROWS_WITH(resolve_region(bounds(0, 11, 0, 5), 10, 20), Catch::Contains("outside"));
  CHECK_THROWS_WITH(resolve_region(bounds(0, 10, 0, 21), 10, 20), Catch::Contains("outside"));
  CHECK_THROWS_WITH(resolve_region(bounds(3, 3, 0, 5), 10, 20), Catch::Contains("empty"));
  CHECK_THROWS_WITH(resolve_region(bounds(4, 3, 0, 5), 10, 20), Catch::Contains("inverted"));
  RegionRequest crop;
  crop.crop_window = std::array<double, 4>{0, 1.5, 0, 1};
  CHECK_THROWS_AS(resolve_region(crop, 10, 20), UsageError);
  RegionRequest both = bounds(0, 1, 0, 1);
  both.crop_window = std::array<double, 4>{0, 1, 0, 1};
  CHECK_THROWS_WITH(resolve_region(both, 10, 20), Catch::Contains("twice"));
}

TEST_CASE("the command line takes regions as one word or four, and refuses bad ones at once",
          "[regions][cli]") {
  ScratchDir dir;
  const std::string scene = quoted(test_scene("reflect.ray")) + " -q --resolution 40x30 ";
  const CommandResult full = run_clrt(scene + "-o " + dir.file("full.pfm"));
  REQUIRE(full.exit_code == 0);
  const CommandResult words =
      run_clrt(scene + "--pixel-bounds 5 25 10 12 -o " + dir.file("words.pfm"));
  const CommandResult commas = run_clrt(scene + "--pixel-bounds=5,25,10,12 -o " +
                                        dir.file("commas.pfm") + " --device all --wavefront 1024",
                                        "POCL_DEVICES='pthread pthread'");
  INFO(words.output << commas.output);
  REQUIRE(words.exit_code == 0);
  REQUIRE(commas.exit_code == 0);
  CHECK(file_bytes(dir.file("words.pfm")) == file_bytes(dir.file("commas.pfm")));
  CHECK(file_bytes(dir.file("words.pfm")).rfind("PF\n20 2\n", 0) == 0);

  for (const char* bad : {"--pixel-bounds 0 41 0 5", "--pixel-bounds 5,5,0,5",
                          "--crop-window 0.5,0.2,0,1", "--pixel-bounds 1,2,3",
                          "--pixel-bounds 0.5,2,0,1"}) {
    const CommandResult r = run_clrt(scene + bad + " -o " + dir.file("bad.png"));
    INFO(bad << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(file_bytes(dir.file("bad.png")).empty());
  }
}
