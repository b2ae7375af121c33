// The lecture's test2.ray and reflect.ray rendered through clrt::render(), against values
// computed by hand and by the independent double-precision tracer of reference_tracer.cpp,
// within 1 in 8 bits.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <utility>

#include "reference_tracer.hpp"
#include "render_support.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

// test2.ray, read by hand: a unit green sphere (ka .3, kd .7, no highlight) under white ambient
// light and a 0.6 point light at (3, 3, 3), on a purple background.
RefScene test2_reference() {
  RefScene s(ContractCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 500, 300), {0.5, 0, 0.5},
             {1, 1, 1});
  s.materials = {{{0, 1, 0}, 0.3, 0.7, 0, 0, 0}};
  s.spheres = {{{0, 0, 0}, 1, 0}};
  s.lights = {{{0.6, 0.6, 0.6}, {3, 3, 3}, {}, false}};
  return s;
}

// reflect.ray, read by hand: `scale` then `translate` place the spheres at their centres below;
// the small ones rest on the plane y = -1; the big white one is a mirror (kr .8).
RefScene reflect_reference() {
  RefScene s(ContractCamera({-2, 1.5, 10}, {0, 0, 0}, {0, 1, 0}, 45, 500, 300),
             {0.078, 0.361, 0.753}, {1, 1, 1});
  s.materials = {{{1, 0, 0}, 0.3, 0.7, 0.5, 100, 0.5},
                 {{0, 1, 0}, 0.3, 0.7, 0.5, 100, 0.5},
                 {{0, 0, 1}, 0.3, 0.7, 0.5, 100, 0.5},
                 {{1, 1, 1}, 0.1, 0.3, 3, 100, 0.8},
                 {{0.6, 0.6, 0.6}, 0.3, 0.7, 1.0, 50, 0.5}};
  s.spheres = {{{-2, -0.5, 0}, 0.5, 0},
               {{-0.25, -0.25, 0}, 0.75, 1},
               {{2, 0.25, 0}, 1.25, 2},
               {{-1.5, 1.25, -3}, 2, 3}};
  s.planes = {{-1, 4}};
  s.lights = {{{1, 1, 1}, {5, 9, 10}, {}, false}};
  return s;
}

const Rgba8Image& rendered(const std::string& name) {
  static std::map<std::string, Rgba8Image> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, quantize(render_file(test_scene(name)))).first;
  return it->second;
}

std::string text_of(const std::array<int, 3>& c) {
  std::ostringstream out;
  out << "(" << c[0] << ", " << c[1] << ", " << c[2] << ")";
  return out.str();
}

#define CHECK_PIXEL(image, i, j, expected)                                               \
  do {                                                                                   \
    const std::array<int, 3> got_ = pixel_rgb((image), (i), (j)), want_ = (expected);    \
    INFO("pixel (" << (i) << ", " << (j) << "): rendered " << text_of(got_) << ", expected " \
                   << text_of(want_));                                                   \
    CHECK(within_one(got_, want_));                                                      \
  } while (0)

// Every pixel that the reference shows is away from any edge must match it within 1; such
// pixels must be most of the image, so the check cannot pass by skipping.
void check_robust_pixels(const Rgba8Image& image, const RefScene& scene) {
  const int w = scene.camera.width, h = scene.camera.height;
  REQUIRE(image.width == w);
  REQUIRE(image.height == h);
  int robust = 0, wrong = 0;
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      if (!robust_pixel(scene, i, j, RefMode::Trace)) continue;
      ++robust;
      const auto want = quantise(image_colour(scene, i + 0.5, j + 0.5, RefMode::Trace));
      if (within_one(pixel_rgb(image, i, j), want)) continue;
      if (++wrong <= 10) CHECK_PIXEL(image, i, j, want);
    }
  }
  CHECK(wrong == 0);
  CHECK(robust > 0.9 * w * h);
}

// The first robust pixel, scanning rows from the top, for which `wanted` holds.
std::optional<std::pair<int, int>> find_pixel(const RefScene& scene,
                                              const std::function<bool(double, double)>& wanted) {
  for (int j = 0; j < scene.camera.height; ++j)
    for (int i = 0; i < scene.camera.width; ++i)
      if (wanted(i + 0.5, j + 0.5) && robust_pixel(scene, i, j, RefMode::Trace))
        return std::make_pair(i, j);
  return std::nullopt;
}

// The floor point seen through image point (x, y) when the floor is what the ray meets first.
std::optional<Vec3> floor_point(const RefScene& scene, double x, double y) {
  const Vec3 d = scene.camera.direction(x, y);
  const RefHit hit = closest_hit(scene, scene.camera.eye, d);
  if (hit.object != static_cast<int>(scene.spheres.size())) return std::nullopt;
  return scene.camera.eye + d * hit.t;
}

// The floor's mirror ray from the floor point seen through (x, y) meets nothing.
bool reflects_sky(const RefScene& scene, double x, double y) {
  const Vec3 d = scene.camera.direction(x, y);
  const std::optional<Vec3> p = floor_point(scene, x, y);
  return p && closest_hit(scene, *p + Vec3{0, 1e-4, 0}, {d.x, -d.y, d.z}).object < 0;
}

}  // namespace

TEST_CASE("test2.ray: the corners are the background colour exactly", "[render][pixels]") {
  const Rgba8Image& image = rendered("test2.ray");
  const std::array<int, 3> purple = {128, 0, 128};  // round(0.5 * 255) = round(127.5)
  CHECK(pixel_rgb(image, 0, 0) == purple);
  CHECK(pixel_rgb(image, 499, 0) == purple);
  CHECK(pixel_rgb(image, 0, 299) == purple);
}

TEST_CASE("test2.ray: the sphere's lit and unlit sides", "[render][pixels]") {
  const Rgba8Image& image = rendered("test2.ray");
  const RefScene scene = test2_reference();
  // The centre pixel sees (almost exactly) the sphere's point (0, 0, 1), normal +z:
  // L = (3, 3, 2) / sqrt(22), N.L = 2 / sqrt(22); green = .3 * 1 + .7 * .6 * N.L.
  const double green = 0.3 + 0.7 * 0.6 * 2 / std::sqrt(22.0);
  CHECK_PIXEL(image, 250, 150, (std::array<int, 3>{0, quantise({0, green, 0})[1], 0}));
  CHECK_PIXEL(image, 250, 150, quantise(image_colour(scene, 250.5, 150.5, RefMode::Trace)));
  // A point facing away from the light, lower left: ambient only, .3 green. On the unit sphere
  // at the origin a point is its own normal.
  const Vec3 n = normalize(Vec3{-0.6, -0.6, 0.53});
  REQUIRE(dot(n, Vec3{3, 3, 3} - n) < 0);
  const auto [x, y] = scene.camera.image_point(normalize(n - scene.camera.eye));
  CHECK_PIXEL(image, static_cast<int>(x), static_cast<int>(y), (std::array<int, 3>{0, 77, 0}));
}

TEST_CASE("test2.ray matches the reference tracer", "[render][pixels]") {
  check_robust_pixels(rendered("test2.ray"), test2_reference());
}

TEST_CASE("reflect.ray: background, floor in and out of shadow, mirror", "[render][pixels]") {
  const Rgba8Image& image = rendered("reflect.ray");
  const RefScene scene = reflect_reference();
  const Vec3 floor_colour{0.6, 0.6, 0.6};
  const Vec3& sky = scene.background;

  SECTION("a top corner is the background colour exactly") {
    REQUIRE(visibility(scene, 499.5, 0.5) == Visibility::Background);
    CHECK(pixel_rgb(image, 499, 0) == (std::array<int, 3>{20, 92, 192}));
  }
  SECTION("the floor in shadow, reflecting the sky: ambient only, plus kr times the sky") {
    const auto pixel = find_pixel(scene, [&](double x, double y) {
      return visibility(scene, x, y) == Visibility::Shadowed && reflects_sky(scene, x, y);
    });
    REQUIRE(pixel);
    // (1 - kr) ka La C + kr * background.
    const Vec3 expected = floor_colour * (0.5 * 0.3) + sky * 0.5;
    CHECK_PIXEL(image, pixel->first, pixel->second, quantise(expected));
  }
  SECTION("the floor in the light, reflecting the sky: every term by hand") {
    const auto pixel = find_pixel(scene, [&](double x, double y) {
      return visibility(scene, x, y) == Visibility::Lit && reflects_sky(scene, x, y);
    });
    REQUIRE(pixel);
    const double x = pixel->first + 0.5, y = pixel->second + 0.5;
    const Vec3 p = *floor_point(scene, x, y);
    const Vec3 n{0, 1, 0}, v = -scene.camera.direction(x, y);
    const Vec3 l = normalize(Vec3{5, 9, 10} - p);
    const Vec3 r = n * (2 * dot(n, l)) - l;
    const double local = 0.3 * 0.6 + 0.7 * 0.6 * dot(n, l) + 1.0 * std::pow(std::max(0.0, dot(r, v)), 50);
    const Vec3 expected = Vec3{local, local, local} * 0.5 + sky * 0.5;
    CHECK_PIXEL(image, pixel->first, pixel->second, quantise(expected));
  }
  SECTION("the mirror sphere's centre") {
    const auto [x, y] = scene.camera.image_point(normalize(Vec3{-1.5, 1.25, -3} - scene.camera.eye));
    const int i = static_cast<int>(x), j = static_cast<int>(y);
    REQUIRE(robust_pixel(scene, i, j, RefMode::Trace));
    CHECK_PIXEL(image, i, j, quantise(image_colour(scene, i + 0.5, j + 0.5, RefMode::Trace)));
  }
}

TEST_CASE("reflect.ray matches the reference tracer", "[render][pixels]") {
  check_robust_pixels(rendered("reflect.ray"), reflect_reference());
}

TEST_CASE("the shipped lecture scenes render like the test copies", "[render][pixels]") {
  for (const char* name : {"test2.ray", "reflect.ray"}) {
    INFO(name);
    const std::string shipped = std::string(CLRT_SOURCE_DIR) + "/scenes/" + name;
    REQUIRE(std::filesystem::exists(shipped));
    const FloatImage a = render_file(shipped), b = render_file(test_scene(name));
    CHECK(a.width == b.width);
    CHECK(a.height == b.height);
    CHECK(a.rgb == b.rgb);
  }
}
