// Path mode against physics: white furnaces (a closed energy balance that must come out exactly,
// sample by sample) and convergence (the error against a long render falls as N^-1/2; a plateau
// would mean bias, a steeper fall correlated samples).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

// One sphere of `material` (the .ray material line's numbers) in a background of radiance 1,
// no lights: every path escapes into the background after its bounces on the sphere.
std::string furnace(const ScratchDir& dir, const std::string& material) {
  const std::string path = dir.file("furnace.ray");
  std::ofstream(path) << "eye 0 0 4\nlookat 0 0 0\nfov 40\nbackground 1 1 1\nresolution 24 24\n"
                         "maxdepth 30\nmaterial "
                      << material << "\nsphere 0 0 0 1\n";
  return path;
}

void path_mode(RenderOptions& o) {
  o.mode = RenderMode::Path;
  o.samples = 8;
}

double rms_difference(const FloatImage& a, const FloatImage& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const double d = static_cast<double>(a.rgb[i]) - b.rgb[i];
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(a.rgb.size()));
}

}  // namespace

TEST_CASE("a white furnace: materials that lose no light render every pixel 1", "[path]") {
  const ScratchDir dir;
  // r g b ka kd ks n kr kt ior; each mixture's lobe weights sum to 1 in every channel (the
  // Lambertian lobe's is kd (1 - kr - kt)). No mixture of glass and a diffuse lobe: inside the
  // sphere the diffuse lobe would keep light bouncing until the maximum depth.
  for (const char* material : {"1 1 1 0 1 0 1 0 0",           // Lambertian
                               "1 1 1 0 0 0 1 1 0",           // mirror
                               "1 1 1 0 0 0 1 0 1 1.5",       // glass
                               "1 1 1 0 1 0 1 0.5 0",         // half Lambertian, half mirror
                               "1 1 1 0 1 0 1 0.3 0.7 1.33"}) {  // mirror and glass
    INFO("material " << material);
    for (const IntegratorKind integrator : {IntegratorKind::Wavefront, IntegratorKind::Megakernel}) {
      const FloatImage image = render_file(furnace(dir, material), [&](RenderOptions& o) {
        path_mode(o);
        o.integrator = integrator;
      });
      float lowest = 2, highest = 0;
      for (float v : image.rgb) {
        lowest = std::min(lowest, v);
        highest = std::max(highest, v);
      }
      CHECK(lowest >= 1.0f - 1e-6f);
      CHECK(highest <= 1.0f + 1e-6f);
    }
  }
}

TEST_CASE("a grey furnace: the sphere renders its albedo", "[path]") {
  const ScratchDir dir;
  struct Case {
    const char* material;
    float albedo[3];
  };
  // kd C = (1, 2, 1) reflects more than it receives: scaled down by its largest channel.
  for (const Case& c : {Case{"0.5 0.5 0.5 0 1 0 1 0 0", {0.5f, 0.5f, 0.5f}},
                        Case{"0.5 1 0.5 0 2 0 1 0 0", {0.5f, 1.0f, 0.5f}}}) {
    INFO("material " << c.material);
    const FloatImage image = render_file(furnace(dir, c.material), path_mode);
    // The middle 8x8 pixels lie wholly on the sphere; the corners wholly on the background.
    for (int y = 8; y < 16; ++y)
      for (int x = 8; x < 16; ++x)
        for (int k = 0; k < 3; ++k)
          CHECK(image.rgb[3 * (y * 24 + x) + k] == Approx(c.albedo[k]).margin(1e-6));
    CHECK(image.rgb[0] == 1.0f);
  }
}

TEST_CASE("the error against a long render falls as one over the root of the samples",
          "[path][convergence]") {
  const std::string scene = test_scene("path-lobes.ray");
  const auto with = [](int samples, std::uint32_t seed) {
    return [=](RenderOptions& o) {
      o.mode = RenderMode::Path;
      o.samples = samples;
      o.seed = seed;
    };
  };
  const FloatImage reference = render_file(scene, with(32768, 1));
  std::vector<double> x, y;
  for (int samples : {4, 16, 64, 256, 1024}) {
    const double error = rms_difference(render_file(scene, with(samples, 2)), reference);
    INFO(samples << " samples: RMS error " << error);
    CHECK(error > 0);
    x.push_back(std::log(static_cast<double>(samples)));
    y.push_back(std::log(error));
  }
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  INFO("log-log slope " << slope);
  CHECK(slope == Approx(-0.5).margin(0.05));
}
