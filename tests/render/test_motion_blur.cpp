// Motion blur (`endpose`, `shutter`, docs/scene-format.md) against closed forms. A pixel sees a
// moving object for the share of the shutter's time that its rays hit it:
// - a sphere of radius r crossing the view at constant speed covers the rays on its path for
//   2r over the length of the path, wherever they are on it;
// - a thin bar of half-width w turning at constant angular speed through a quarter turn about
//   the view axis covers a point at radius p and polar angle phi for the time the bar's angle
//   is within asin(w / p) of phi: 2 asin(w / p) over pi / 2. A rotation interpolated other than
//   by slerp turns at a varying speed (normalised linear interpolation 17% faster in the middle
//   of a quarter turn than at its ends), which this tells apart.
// The objects glow (path mode) or are lit by ambient light alone (the Whitted modes), on black,
// so a pixel's value is that share.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace motion_blur_test {

constexpr int kBlurSide = 101;  // odd: the middle pixel's centre is on the view axis
constexpr double kBlurFov = 40, kBlurDepth = 10;

struct Setup {
  RenderMode mode;
  const char* integrator;
};

const Setup kSetups[] = {{RenderMode::Cast, "wavefront"}, {RenderMode::Trace, "megakernel"},
                         {RenderMode::Path, "wavefront"}, {RenderMode::Path, "megakernel"}};

// `objects` seen head-on from the origin, down -z, with `samples` a pixel.
FloatImage render_objects(const std::string& objects, const Setup& setup, int samples = 256) {
  ScratchDir dir;
  const std::string scene = "eye 0 0 0\nlookat 0 0 -1\nup 0 1 0\nfov " + std::to_string(kBlurFov) +
                            "\nresolution " + std::to_string(kBlurSide) + " " + std::to_string(kBlurSide) +
                            "\nsamples " + std::to_string(samples) + "\nmaxdepth 1\nmaterial 1 1 1 1 0 0 1 0 0 1\n" +
                            (setup.mode == RenderMode::Path ? "emission 1 1 1\n" : "light 1 1 1 ambient\n") +
                            objects;
  return render_file(dir.write("motion.ray", scene), [&](RenderOptions& o) {
    o.mode = setup.mode;
    o.integrator = setup.integrator;
  });
}

// Pixels per scene unit at kBlurDepth.
double pixels_per_unit() { return kBlurSide / (2 * kBlurDepth * std::tan(kBlurFov * M_PI / 360)); }

struct Probe {
  double value;  // the pixel's red channel
  double x, y;   // its centre, in scene units at kBlurDepth
};

// Pixel (i, j) and its centre.
Probe pixel(const FloatImage& image, int i, int j) {
  const double k = pixels_per_unit();
  return {image.rgb[3 * (static_cast<std::size_t>(j) * kBlurSide + static_cast<std::size_t>(i))],
          (i + 0.5 - kBlurSide / 2.0) / k, (kBlurSide / 2.0 - j - 0.5) / k};
}

// The pixel nearest the point (x, y) at kBlurDepth, which must be in view.
Probe probe(const FloatImage& image, double x, double y) {
  const double k = pixels_per_unit();
  const int i = static_cast<int>(std::floor(kBlurSide / 2.0 + x * k));
  const int j = static_cast<int>(std::floor(kBlurSide / 2.0 - y * k));
  REQUIRE((i >= 0 && i < kBlurSide && j >= 0 && j < kBlurSide));
  return pixel(image, i, j);
}

// A ray towards (x, 0, -kBlurDepth) passes within r of a sphere's centre on that line for
// |x - centre| < r sqrt(1 + x^2 / kBlurDepth^2): the rays are not parallel.
double crossing(double x, double r, double path) {
  return 2 * r * std::sqrt(1 + x * x / (kBlurDepth * kBlurDepth)) / path;
}

const char* mode_name(RenderMode m) {
  return m == RenderMode::Cast ? "cast" : m == RenderMode::Trace ? "trace" : "path";
}

}  // namespace motion_blur_test

using namespace motion_blur_test;

TEST_CASE("a sphere crossing the view covers each pixel on its path for its diameter over the "
          "path's length",
          "[render][motion]") {
  const double r = 0.5, from = -2.5, to = 2.5;
  const std::string sphere = "translate " + std::to_string(from) + " 0 -10\nendpose\ntranslate " +
                             std::to_string(to - from) + " 0 0\nsphere 0 0 0 " + std::to_string(r) + "\n";
  for (const Setup& setup : kSetups) {
    INFO(mode_name(setup.mode) << ", " << setup.integrator);
    const FloatImage image = render_objects(sphere, setup);
    // The middle row's pixels from x = -1.5 to 1.5, summed: a single pixel's samples meet the
    // ends of its window in time at random (its footprint spans a seventh of the window).
    double seen = 0, expected = 0;
    for (int i = 0; i < kBlurSide; ++i) {
      const Probe p = pixel(image, i, kBlurSide / 2);
      if (std::fabs(p.x) > 1.5) continue;
      seen += p.value;
      expected += crossing(p.x, r, to - from);
    }
    CHECK(seen == Approx(expected).epsilon(0.01));
    CHECK(probe(image, 0, 0.7).value == 0);  // above the path
    CHECK(probe(image, 3.2, 0).value == 0);  // beyond its end

    // A shutter that closes before the sphere reaches the middle, and one open for an instant.
    const FloatImage early = render_objects("shutter 0 0.25\n" + sphere, setup);
    CHECK(probe(early, 0, 0).value == 0);
    const Probe swept = probe(early, -1.9, 0);  // its window lies within the shutter's sweep
    CHECK(swept.value == Approx(crossing(swept.x, r, (to - from) / 4)).epsilon(0.03));
    const FloatImage instant = render_objects("shutter 0.5 0.5\n" + sphere, setup);
    CHECK(probe(instant, 0, 0).value == 1);
    CHECK(probe(instant, 0.6, 0).value == 0);
    // Times beyond the motion hold its last pose.
    const FloatImage after = render_objects("shutter 1 3\n" + sphere, setup);
    CHECK(probe(after, 2.5, 0).value == 1);
    CHECK(probe(after, 0, 0).value == 0);
  }
}

TEST_CASE("a bar turning a quarter turn covers each angle for the same time: rotation is "
          "interpolated at constant angular speed",
          "[render][motion]") {
  const double half_width = 0.2;
  // The bar lies along x; turning about z (the view axis) commutes with moving along it.
  const std::string bar = "scale 3 0.2 0.005\ntranslate 0 0 -10\nendpose\nrotatez 90\ncube\n";
  for (const Setup& setup : kSetups) {
    INFO(mode_name(setup.mode) << ", " << setup.integrator);
    const FloatImage image = render_objects(bar, setup, 1024);
    // Pixels at radii 1.8 to 2.2 within 6 degrees of each angle, summed: a single pixel's
    // samples meet the window's edges at random (its footprint spans a tenth of the window).
    for (const double degrees : {20.0, 45.0, 70.0}) {
      double seen = 0, expected = 0;
      for (int j = 0; j < kBlurSide; ++j)
        for (int i = 0; i < kBlurSide; ++i) {
          const Probe p = pixel(image, i, j);
          const double radius = std::hypot(p.x, p.y), phi = std::atan2(p.y, p.x) * 180 / M_PI;
          if (radius < 1.8 || radius > 2.2 || std::fabs(phi - degrees) > 6) continue;
          seen += p.value;
          expected += 2 * std::asin(half_width / radius) / (M_PI / 2);
        }
      INFO("at " << degrees << " degrees");
      CHECK(seen == Approx(expected).epsilon(0.02));
    }
    CHECK(probe(image, -1.5, 1.5).value == 0);  // the quadrant it never turns through
  }
}

TEST_CASE("endpose: objects move from the pose at endpose to the current one, until reset",
          "[render][motion]") {
  // Both spheres after one endpose move; after reset the third stands still.
  const std::string scene =
      "translate -2 0 -10\nendpose\ntranslate 4 0 0\nsphere 0 2 0 0.25\nsphere 0 -2 0 0.25\nreset\n"
      "sphere 0 0 -10 0.5\n";
  const FloatImage image = render_objects(scene, kSetups[0]);
  CHECK(probe(image, 1, 2).value == Approx(0.125).epsilon(0.03));
  CHECK(probe(image, 1, -2).value == Approx(0.125).epsilon(0.03));
  CHECK(probe(image, 0, 0).value == 1);
  CHECK(probe(image, 0.6, 0).value == 0);
}
