// The thin lens (`lens RADIUS FOCUS`, docs/scene-format.md) against the closed form of its
// circle of confusion: a small sphere off the plane in focus images as the sphere's disc spread
// over a disc of diameter 2 r f |z - d| / (z d) pixels, with the light it covers kept; on the
// plane in focus it stays as sharp as through a pinhole.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

constexpr int kSide = 64;
constexpr double kFov = 30, kSphereRadius = 0.2, kSphereDistance = 10;

// A white sphere lit by ambient light alone (cast mode: exactly 1 where a ray hits it) on
// black, straight ahead at kSphereDistance; `lens` is the scene's lens line.
FloatImage sphere_image(const std::string& lens) {
  ScratchDir dir;
  const std::string scene = "eye 0 0 0\nlookat 0 0 -1\nup 0 1 0\nfov " + std::to_string(kFov) +
                            "\nresolution " + std::to_string(kSide) + " " + std::to_string(kSide) +
                            "\nsamples 256\nlight 1 1 1 ambient\nmaterial 1 1 1 1 0 0 1 0 0 1\n"
                            "sphere 0 0 " + std::to_string(-kSphereDistance) + " " +
                            std::to_string(kSphereRadius) + "\n" + lens;
  return render_file(dir.write("lens.ray", scene),
                     [](RenderOptions& o) { o.mode = RenderMode::Cast; });
}

struct Spread {
  double covered = 0;     // sum of the pixels: the area the sphere covers, in pixels
  double mean_r2 = 0;     // the mean squared distance from the image's centre, by coverage
  double farthest = 0;    // the farthest pixel centre with any coverage
};

Spread spread_of(const FloatImage& image) {
  Spread s;
  double moment = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double v = image.rgb[3 * (y * image.width + x)];
      const double dx = x + 0.5 - kSide / 2.0, dy = y + 0.5 - kSide / 2.0;
      s.covered += v;
      moment += v * (dx * dx + dy * dy);
      if (v > 0) s.farthest = std::fmax(s.farthest, std::sqrt(dx * dx + dy * dy));
    }
  s.mean_r2 = moment / s.covered;
  return s;
}

}  // namespace

TEST_CASE("a thin lens blurs a point off the plane in focus into its circle of confusion",
          "[render][lens]") {
  const double f = kSide / (2 * std::tan(kFov * M_PI / 360));  // the focal length in pixels
  const double sphere = f * kSphereRadius / kSphereDistance;    // the sphere's image radius
  const double radius = 0.5, focus = 5;
  // The circle of confusion's radius in pixels: r f |z - d| / (z d).
  const double blur = radius * f * std::fabs(kSphereDistance - focus) / (kSphereDistance * focus);
  REQUIRE(blur > 2 * sphere);

  const Spread pinhole = spread_of(sphere_image(""));
  const Spread blurred = spread_of(sphere_image("lens 0.5 5\n"));
  const Spread sharp = spread_of(sphere_image("lens 0.5 10\n"));
  INFO("pinhole covers " << pinhole.covered << ", lens " << blurred.covered << ", in focus "
                         << sharp.covered << " pixels; blur radius " << blur);
  const double disc = M_PI * sphere * sphere;
  CHECK(pinhole.covered == Approx(disc).epsilon(0.05));
  CHECK(blurred.covered == Approx(pinhole.covered).epsilon(0.05));  // the lens keeps the light
  CHECK(sharp.covered == Approx(pinhole.covered).epsilon(0.05));
  // Second moments add under the blur: a uniform disc of radius a has a mean r^2 of a^2 / 2, and
  // a pixel's box adds 1/6.
  const double box = 1.0 / 6;
  INFO("mean r^2: pinhole " << pinhole.mean_r2 << ", lens " << blurred.mean_r2 << ", in focus "
                            << sharp.mean_r2);
  CHECK(pinhole.mean_r2 == Approx(sphere * sphere / 2 + box).epsilon(0.05));
  CHECK(blurred.mean_r2 == Approx((sphere * sphere + blur * blur) / 2 + box).epsilon(0.02));
  CHECK(sharp.mean_r2 == Approx(pinhole.mean_r2).epsilon(0.05));
  // Nothing lands beyond the blurred disc (half a pixel's diagonal for the pixel's own size).
  CHECK(blurred.farthest <= blur + sphere + std::sqrt(0.5));
  CHECK(blurred.farthest >= blur + sphere - 1.5);
  CHECK(sharp.farthest <= sphere + std::sqrt(0.5) + 0.3);
}

TEST_CASE("lens 0 is the pinhole, the same bits", "[render][lens]") {
  CHECK(same_bits(sphere_image(""), sphere_image("lens 0 3\n")));
}
