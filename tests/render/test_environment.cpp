// `environment FILE [SCALE]` (docs/scene-format.md#environment): escaping rays see the texel of
// Mitsuba 3's envmap orientation, turned by the rotation in force, in every mode; a constant
// environment renders as a background of the same radiance (the same bits in the Whitted modes,
// the same light in path mode, where it is also sampled); PNG is decoded from sRGB; and the
// command's errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "image/image.hpp"
#include "png_header.hpp"
#include "render/integrator_names.hpp"
#include "render_support.hpp"
#include "scene/scene.hpp"
#include "scene/source_location.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

// An 8 x 4 map whose texel (i, j) has radiance (i + 1, j + 1, 0.5) / 8.
FloatImage texel_map() {
  std::vector<float> rgb;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 8; ++i) rgb.insert(rgb.end(), {(i + 1) / 8.0f, (j + 1) / 8.0f, 0.5f});
  return FloatImage(8, 4, rgb);
}

// The unit direction at the centre of texel (i, j) of an 8 x 4 map, by Mitsuba's envmap
// mapping: u = (i + 1/2) / 8 = phi / (2 pi), v = (j + 1/2) / 4 = theta / pi.
std::array<double, 3> texel_direction(int i, int j) {
  const double phi = 2 * kPi * (i + 0.5) / 8, theta = kPi * (j + 0.5) / 4;
  return {std::sin(phi) * std::sin(theta), std::cos(theta), -std::cos(phi) * std::sin(theta)};
}

// A one-pixel view along `d` from the origin, of nothing but the environment.
std::string view_along(const ScratchDir& dir, std::array<double, 3> d, const std::string& turn) {
  const std::string path = dir.file("view.ray");
  std::ofstream out(path);
  out.precision(17);
  out << "eye 0 0 0\nlookat " << d[0] << ' ' << d[1] << ' ' << d[2] << "\nup "
      << (std::fabs(d[1]) > 0.9 ? "1 0 0" : "0 1 0") << "\nfov 0.5\nresolution 1 1\n"
      << turn << "environment map.pfm\n";
  return path;
}

// A grey sphere (albedo 0.5, no ambient) in a constant sky of radiance 1: the background's, or
// an environment image's.
std::string grey_sphere(const ScratchDir& dir, bool environment) {
  const std::string path = dir.file(environment ? "env.ray" : "sky.ray");
  std::ofstream(path) << "eye 0 0 4\nlookat 0 0 0\nfov 40\nresolution 24 24\nmaxdepth 4\n"
                      << (environment ? "environment flat.pfm\n" : "background 1 1 1\n")
                      << "material 0.5 0.5 0.5 0 1 0 1 0 0\nsphere 0 0 0 1\nlight 1 1 1 point 2 3 4\n";
  return path;
}

double mean(const FloatImage& image) {
  double sum = 0;
  for (float v : image.rgb) sum += v;
  return sum / static_cast<double>(image.rgb.size());
}

}  // namespace

TEST_CASE("escaping rays see the environment's texel along them, turned by the rotation",
          "[render][environment]") {
  const ScratchDir dir;
  write_image(dir.file("map.pfm"), texel_map());
  struct Turn {
    const char* command;
    double degrees;  // about +y: the map's direction d shows along R d
  };
  // Every mode looks the map up alike; the turns are checked in one.
  for (const Turn& turn : {Turn{"", 0}, Turn{"rotatey 90\n", 90}, Turn{"rotatey -30\n", -30}}) {
    for (const auto mode : {RenderMode::Trace, RenderMode::Cast, RenderMode::Path}) {
      if (turn.degrees != 0 && mode != RenderMode::Trace) continue;
      for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 8; ++i) {
          const auto m = texel_direction(i, j);
          const double a = turn.degrees * kPi / 180;
          const std::array<double, 3> d = {std::cos(a) * m[0] + std::sin(a) * m[2], m[1],
                                           -std::sin(a) * m[0] + std::cos(a) * m[2]};
          INFO("texel (" << i << ", " << j << ") " << turn.command << "mode " << static_cast<int>(mode));
          const FloatImage image = render_file(view_along(dir, d, turn.command), [mode](RenderOptions& o) {
            o.mode = mode;
            o.samples = 1;
          });
          CHECK(image.rgb[0] == (i + 1) / 8.0f);
          CHECK(image.rgb[1] == (j + 1) / 8.0f);
          CHECK(image.rgb[2] == 0.5f);
        }
      }
    }
  }
}

TEST_CASE("a constant environment renders as a background of the same radiance",
          "[render][environment]") {
  const ScratchDir dir;
  write_image(dir.file("flat.pfm"), FloatImage(4, 2, std::vector<float>(24, 1.0f)));
  SECTION("the Whitted modes: the same bits") {
    for (const auto mode : {RenderMode::Trace, RenderMode::Cast}) {
      const auto with = [mode](RenderOptions& o) { o.mode = mode; };
      CHECK(same_bits(render_file(grey_sphere(dir, true), with), render_file(grey_sphere(dir, false), with)));
    }
  }
  SECTION("path mode: the same light, the environment sampled as well") {
    for (const std::string& integrator : integrator_names()) {
      INFO(integrator);
      const auto with = [&](RenderOptions& o) {
        o.mode = RenderMode::Path;
        o.samples = 1024;
        o.integrator = integrator;
      };
      const FloatImage sky = render_file(grey_sphere(dir, false), with);
      const FloatImage env = render_file(grey_sphere(dir, true), with);
      // The point light adds the same to both; the noise of 576 pixels x 1024 samples is
      // below 0.1% of the mean.
      CHECK(mean(env) == Approx(mean(sky)).epsilon(0.003));
      CHECK_FALSE(same_bits(env, sky));
    }
  }
}

TEST_CASE("a PNG environment is decoded from sRGB, and a scale multiplies it", "[render][environment]") {
  const ScratchDir dir;
  Rgba8Image png;
  png.width = 2;
  png.height = 1;
  png.frames = {{128, 64, 255, 255, 128, 64, 255, 255}};
  write_image(dir.file("map.png"), png);
  const std::string path = dir.file("png.ray");
  std::ofstream(path) << "eye 0 0 0\nlookat 0 0 -1\nfov 0.5\nresolution 1 1\nenvironment map.png 2\n";
  const FloatImage image = render_file(path);
  const auto linear = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  CHECK(image.rgb[0] == Approx(2 * linear(128 / 255.0)).epsilon(1e-6));
  CHECK(image.rgb[1] == Approx(2 * linear(64 / 255.0)).epsilon(1e-6));
  CHECK(image.rgb[2] == Approx(2.0).epsilon(1e-6));
}

TEST_CASE("environment: a bad file, scale or transform is an error at its place", "[render][environment]") {
  const ScratchDir dir;
  write_image(dir.file("map.pfm"), texel_map());
  write_image(dir.file("negative.pfm"), FloatImage(1, 1, {0.5f, -1.0f, 0.5f}));
  // A header alone, declaring 65536x4096: it was decoded (4.3 GB, 12 s) before being refused.
  std::ofstream(dir.file("wide.png"), std::ios::binary) << png_header(65536, 4096);
  std::ofstream(dir.file("photo.png"), std::ios::binary) << std::string("\xff\xd8\xff\xe0\x00\x10JFIF", 10);
  struct Case {
    const char* text;
    const char* message;
  };
  for (const Case& c : {Case{"environment missing.pfm", "1:13: error: cannot read the environment image"},
                        Case{"environment map.pfm -1", "1:21: error: the environment's scale must be in [0, 1e12]"},
                        Case{"environment map.pfm 1 2", "1:23: error: wrong number of arguments: environment takes 1 or 2"},
                        Case{"scale 2 1 1\nenvironment map.pfm", "2:13: error: the environment turns with"},
                        Case{"environment negative.pfm", "1:13: error: the environment image"},
                        Case{"environment wide.png", "wide.png: it is "
                                                     "65536x4096 pixels; an environment may have at most 16384 on a side"},
                        Case{"environment photo.png", "photo.png: the name says PNG, but the file holds a JPEG image"}}) {
    INFO(c.text);
    const std::string path = dir.file("bad.ray");
    std::ofstream(path) << c.text << "\n";
    try {
      load_scene(path);
      FAIL("accepted");
    } catch (const SceneError& e) {
      CHECK_THAT(e.what(), Catch::Matchers::Contains(c.message));
    }
  }
}

TEST_CASE("glossy reflection (--glossy) blurs a mirror by the Phong lobe of its exponent", "[render][glossy]") {
  // A mirror floor (kr 1) seen straight down through a narrow field reflects a map that is white
  // in its top row only (theta below 22.5 degrees) and black elsewhere. A mirror shows the white;
  // with --glossy, a reflection ray drawn from the normalised lobe cos^n about the vertical is
  // white with probability P(cos theta > cos 22.5) = 1 - cos(22.5)^(n + 1).
  const ScratchDir dir;
  std::vector<float> rgb(8 * 8 * 3, 0.0f);
  std::fill(rgb.begin(), rgb.begin() + 8 * 3, 1.0f);
  write_image(dir.file("cap.pfm"), FloatImage(8, 8, rgb));
  const std::string path = dir.file("floor.ray");
  std::ofstream(path) << "eye 0 1 0\nlookat 0 0 0\nup 0 0 -1\nfov 1\nresolution 4 4\n"
                         "environment cap.pfm\nmaterial 1 1 1 0 0 0 10 1 0\nplane\n";
  const double expected = 1 - std::pow(std::cos(kPi / 8), 11);
  for (const std::string& integrator : integrator_names()) {
    INFO(integrator);
    const auto with = [&](bool glossy) {
      return [&, glossy](RenderOptions& o) {
        o.samples = 4096;
        o.glossy = glossy;
        o.integrator = integrator;
      };
    };
    CHECK(mean(render_file(path, with(false))) == 1.0);
    // 65536 draws of a Bernoulli of p = 0.58: a standard error of 0.002.
    CHECK(mean(render_file(path, with(true))) == Approx(expected).margin(0.01));
  }
}
