// An OBJ mesh with an MTL library renders each `usemtl` face in its own material, in every mode
// and with both integrators: two quads facing the camera, lit by ambient light alone (Whitted
// modes) or seen glowing (path mode), on black, so that a pixel is ka Kd La + Ke in the Whitted
// modes (ka 0.2, La 1) and Ke in path mode, worked out here from the MTL's numbers.
#include <catch2/catch.hpp>

#include <array>
#include <string>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace mtl_render_test {

const char* const kObj =
    "mtllib two.mtl\n"
    "v -2 -1 0\nv 0 -1 0\nv 0 1 0\nv -2 1 0\nv 2 -1 0\nv 2 1 0\n"
    "usemtl red\nf 1 2 3 4\n"
    "usemtl green\nf 2 5 6 3\n";

const char* const kMtl =
    "newmtl red\nKd 0.8 0.1 0.1\nKe 0.5 0 0\nillum 1\n"
    "newmtl green\nKd 0.1 0.7 0.2\nKe 0 0.25 0\nillum 1\n";

using Rgb = std::array<float, 3>;

Rgb pixel(const FloatImage& image, int x, int y) {
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * image.width + x);
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

// ka Kd La + Ke in the Whitted modes, Ke in path mode.
Rgb expected(RenderMode mode, const Rgb& kd, const Rgb& ke) {
  if (mode == RenderMode::Path) return ke;
  return {0.2f * kd[0] + ke[0], 0.2f * kd[1] + ke[1], 0.2f * kd[2] + ke[2]};
}

void check_pixel(const Rgb& got, const Rgb& want) {
  for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-6));
}

TEST_CASE("each usemtl face of an OBJ renders in its MTL material, in every mode and integrator",
          "[render][mtl]") {
  ScratchDir dir;
  dir.write("two.obj", kObj);
  dir.write("two.mtl", kMtl);
  const std::string head =
      "eye 0 0 5\nlookat 0 0 0\nfov 60\nresolution 40 20\nbackground 0 0 0\nlight 1 1 1 ambient\n"
      "material 0 0 1 0.2 0.8 0 1 0 0\nemission 0 0 0.5\n";
  const std::string with_mtl = dir.write("with.ray", head + "mesh two.obj\n");
  const std::string without = dir.write("without.ray", head + "mtl off\nmesh two.obj\n");
  for (RenderMode mode : {RenderMode::Cast, RenderMode::Trace, RenderMode::Path})
    for (const char* integrator : {"wavefront", "megakernel"}) {
      INFO("mode " << static_cast<int>(mode) << ", " << integrator);
      const auto adjust = [&](RenderOptions& o) {
        o.mode = mode;
        o.integrator = integrator;
      };
      const FloatImage image = render_file(with_mtl, adjust);
      check_pixel(pixel(image, 10, 10), expected(mode, {0.8f, 0.1f, 0.1f}, {0.5f, 0, 0}));
      check_pixel(pixel(image, 30, 10), expected(mode, {0.1f, 0.7f, 0.2f}, {0, 0.25f, 0}));
      // mtl off: both quads in the scene's material.
      const FloatImage plain = render_file(without, adjust);
      for (int x : {10, 30}) check_pixel(pixel(plain, x, 10), expected(mode, {0, 0, 1}, {0, 0, 0.5f}));
    }
}

}  // namespace mtl_render_test
