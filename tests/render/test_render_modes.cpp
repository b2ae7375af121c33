// --mode cast against trace on tests/render/scenes/shadows.ray, a scene with no reflective or
// transparent material: the two may differ only where a light is blocked. Which pixels those
// are is decided by the reference tracer's own analytic shadow test.
#include <catch2/catch.hpp>

#include <cstring>

#include "reference_tracer.hpp"
#include "render_support.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

// shadows.ray, read by hand.
RefScene shadows_reference() {
  RefScene s(ContractCamera({0, 2, 8}, {0, 0, 0}, {0, 1, 0}, 50, 100, 60), {0.2, 0.3, 0.4},
             {0.2, 0.2, 0.2});
  s.materials = {{{0.9, 0.9, 0.9}, 0.2, 0.8, 0, 1, 0},
                 {{1, 0.3, 0.2}, 0.2, 0.7, 0.4, 20, 0},
                 {{0.2, 0.5, 1}, 0.2, 0.7, 0.4, 20, 0}};
  s.spheres = {{{0, 0, 0}, 1, 1}, {{-2, -0.5, 1}, 0.5, 2}};
  s.planes = {{-1, 0}};
  s.lights = {{{0.5, 0.5, 0.5}, {4, 5, 3}, {}, false},
              {{0.3, 0.3, 0.3}, {-3, 4, -2}, {}, false},
              {{0.2, 0.2, 0.25}, {}, {-1, -2, -1}, true}};
  return s;
}

bool same_rgb_bits(const FloatImage& a, const FloatImage& b, std::size_t pixel) {
  return std::memcmp(&a.rgb[3 * pixel], &b.rgb[3 * pixel], 3 * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("cast and trace agree bit for bit wherever no light is blocked", "[render][modes]") {
  const RefScene scene = shadows_reference();
  const auto in_mode = [](RenderMode mode) {
    return [mode](RenderOptions& o) { o.mode = mode; };
  };
  const FloatImage trace = render_file(test_scene("shadows.ray"), in_mode(RenderMode::Trace));
  const FloatImage cast = render_file(test_scene("shadows.ray"), in_mode(RenderMode::Cast));
  const Rgba8Image trace8 = quantize(trace), cast8 = quantize(cast);
  REQUIRE(trace.width == 100);
  REQUIRE(trace.height == 60);

  int lit = 0, shadowed = 0;
  for (int j = 0; j < 60; ++j) {
    for (int i = 0; i < 100; ++i) {
      if (!robust_pixel(scene, i, j, RefMode::Trace) || !robust_pixel(scene, i, j, RefMode::Cast))
        continue;
      INFO("pixel (" << i << ", " << j << ")");
      const std::size_t p = static_cast<std::size_t>(j) * 100 + static_cast<std::size_t>(i);
      const Visibility seen = visibility(scene, i + 0.5, j + 0.5);
      if (seen == Visibility::Shadowed) {
        ++shadowed;
        CHECK_FALSE(same_rgb_bits(trace, cast, p));
        CHECK(trace.rgb[3 * p] < cast.rgb[3 * p]);
      } else {
        lit += seen == Visibility::Lit;
        CHECK(same_rgb_bits(trace, cast, p));
      }
      // Both modes against the reference, within 1 in 8 bits.
      const auto want_trace = quantise(image_colour(scene, i + 0.5, j + 0.5, RefMode::Trace));
      const auto want_cast = quantise(image_colour(scene, i + 0.5, j + 0.5, RefMode::Cast));
      CHECK(within_one(pixel_rgb(trace8, i, j), want_trace));
      CHECK(within_one(pixel_rgb(cast8, i, j), want_cast));
    }
  }
  // The scene must exercise both kinds of pixel.
  CHECK(shadowed > 200);
  CHECK(lit > 1000);
}
