// generate (kernels/generate.cl) and make_camera (src/render/frame_setup.cpp) against the
// contract's camera model (tests/render/reference_camera.hpp) and hand values.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "cl_fixture.hpp"
#include "reference_camera.hpp"
#include "render/frame_setup.hpp"
#include "render/stage_args.hpp"
#include "shared/ray.h"
#include "test_vectors.hpp"

using namespace clrt;
using test::vec_of;

namespace {

Scene camera_scene(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov) {
  Scene scene;
  scene.camera.eye = eye;
  scene.camera.lookat = lookat;
  scene.camera.up = up;
  scene.camera.fov_degrees = fov;
  return scene;
}

RenderOptions image_options(int width, int height, int samples, std::uint32_t seed = 0) {
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.samples = samples;
  o.seed = seed;
  return o;
}

test::ContractCamera contract_camera(const Scene& scene, int width, int height) {
  const CameraSpec& c = scene.camera;
  return {c.eye, c.lookat, c.up, c.fov_degrees, width, height};
}

// The direction make_camera's fields give for image point (x, y).
Vec3 camera_direction(const dev::Camera& cam, double x, double y) {
  return normalize(vec_of(cam.corner) + vec_of(cam.pixel_dx) * x + vec_of(cam.pixel_dy) * y);
}

// Samples [first_sample, first_sample + pixel_samples) of each pixel from first_pixel on; all
// of each pixel's samples unless told.
std::vector<dev::Ray> generate(const dev::Camera& camera, std::uint32_t first_pixel,
                               std::uint32_t sample_count, std::uint32_t first_sample = 0,
                               std::uint32_t pixel_samples = 0) {
  GenerateArgs args;
  args.camera = test::upload(std::vector<dev::Camera>{camera});
  args.wave = {0,           0, camera.width, first_pixel, first_sample,
               pixel_samples ? pixel_samples : camera.samples, sample_count};
  args.rays = test::allocate<dev::Ray>(sample_count);
  test::run(test::renderer_program(), args, sample_count);
  return test::download(args.rays, sample_count);
}

const Vec3 kEye{0, 0, 5};
const Vec3 kOrigin{0, 0, 0};
const Vec3 kUp{0, 1, 0};

}  // namespace

TEST_CASE("make_camera gives the contract's directions for a 4x2 image with fov 90", "[generate]") {
  // f = 4 / (2 tan 45) = 2, F = -z, R = +x, U = +y: dir(x, y) = (x - 2, 1 - y, -2).
  const dev::Camera cam = make_camera(camera_scene(kEye, kOrigin, kUp, 90), image_options(4, 2, 1));
  CHECK_NEAR_VEC(vec_of(cam.eye), Vec3(0, 0, 5), 0);
  CHECK_NEAR_VEC(camera_direction(cam, 0, 0), normalize(Vec3(-2, 1, -2)), 1e-6);
  CHECK_NEAR_VEC(camera_direction(cam, 4, 2), normalize(Vec3(2, -1, -2)), 1e-6);
  CHECK_NEAR_VEC(camera_direction(cam, 2, 1), Vec3(0, 0, -1), 1e-6);
  CHECK_NEAR_VEC(camera_direction(cam, 0.5, 1.5), normalize(Vec3(-1.5, -0.5, -2)), 1e-6);
  CHECK(cam.width == 4);
  CHECK(cam.height == 2);
  CHECK(cam.samples == 1);
  CHECK(cam.grid_u * cam.grid_v == 1);
}

TEST_CASE("make_camera: up need not be unit or orthogonal, and +x is to the right", "[generate]") {
  const dev::Camera slanted =
      make_camera(camera_scene(kEye, kOrigin, Vec3(0, 3, 1), 90), image_options(4, 2, 1));
  CHECK_NEAR_VEC(camera_direction(slanted, 0, 0), normalize(Vec3(-2, 1, -2)), 1e-6);
  CHECK_NEAR_VEC(camera_direction(slanted, 3, 0.25), normalize(Vec3(1, 0.75, -2)), 1e-6);
  CHECK(camera_direction(slanted, 3.5, 1).x > 0);
}

TEST_CASE("make_camera matches the contract for a general camera", "[generate]") {
  const Scene scene = camera_scene(Vec3(-2, 1.5, 10), kOrigin, kUp, 45);
  const dev::Camera cam = make_camera(scene, image_options(500, 300, 6, 42));
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {0, 0}, {500, 300}, {250, 150}, {0.5, 299.5}, {123.25, 17.75}, {499, 1}}) {
    INFO("image point " << x << ", " << y);
    CHECK_NEAR_VEC(camera_direction(cam, x, y), contract_camera(scene, 500, 300).direction(x, y),
                   1e-6);
  }
  CHECK(cam.samples == 6);
  CHECK(cam.grid_u == 3);
  CHECK(cam.grid_v == 2);
  CHECK(cam.seed == 42);
}

TEST_CASE("stratification grids follow the contract", "[generate]") {
  // gv = the largest divisor of n not above sqrt(n), gu = n / gv.
  const std::vector<std::pair<unsigned, std::pair<unsigned, unsigned>>> expected = {
      {1, {1, 1}}, {2, {2, 1}}, {3, {3, 1}}, {4, {2, 2}},  {6, {3, 2}},   {7, {7, 1}},
      {8, {4, 2}}, {9, {3, 3}}, {12, {4, 3}}, {16, {4, 4}}, {18, {6, 3}}, {64, {8, 8}}};
  for (const auto& [n, grid] : expected) {
    INFO("n = " << n);
    const Grid g = stratification_grid(n);
    CHECK(g.u == grid.first);
    CHECK(g.v == grid.second);
  }
}

TEST_CASE("generate: one sample per pixel goes through the pixel centre", "[generate]") {
  const dev::Camera cam = make_camera(camera_scene(kEye, kOrigin, kUp, 90), image_options(4, 2, 1));
  const std::vector<dev::Ray> rays = generate(cam, 0, 8);
  // Centres (i + 0.5, j + 0.5): directions (i - 1.5, 0.5 - j, -2) before normalising.
  const double xs[4] = {-1.5, -0.5, 0.5, 1.5};
  const double ys[2] = {0.5, -0.5};
  for (std::uint32_t i = 0; i < 8; ++i) {
    INFO("ray " << i);
    const dev::Ray& r = rays[i];
    CHECK_NEAR_VEC(vec_of(r.dir), normalize(Vec3(xs[i % 4], ys[i / 4], -2)), 1e-6);
    CHECK_NEAR_VEC(vec_of(r.origin), kEye, 0);
    CHECK_NEAR_VEC(vec_of(r.weight), Vec3(1, 1, 1), 0);
    CHECK(r.sample == i);
    CHECK(CLRT_RAY_DEPTH(r) == 0);
    CHECK(CLRT_RAY_KIND(r) == CLRT_RAY_CAMERA);
  }
  SECTION("the seed does not move a single sample off the centre") {
    dev::Camera seeded = cam;
    seeded.seed = 12345;
    const std::vector<dev::Ray> again = generate(seeded, 0, 8);
    for (std::size_t i = 0; i < 8; ++i) CHECK(test::same_bits(again[i].dir, rays[i].dir));
  }
}

TEST_CASE("generate: stratified samples lie in their pixel, one per cell", "[generate]") {
  const Scene scene = camera_scene(Vec3(1, 2, 6), Vec3(0, 0.5, 0), kUp, 70);
  const int width = 7, height = 5;
  const std::uint32_t first_pixel = 5, pixels = 23;  // a wave that starts mid-row
  for (int spp : {4, 6}) {
    const dev::Camera cam = make_camera(scene, image_options(width, height, spp, 3));
    const Grid grid = stratification_grid(static_cast<unsigned>(spp));
    const std::vector<dev::Ray> rays = generate(cam, first_pixel, pixels * spp);
    bool jittered = false;
    for (std::uint32_t p = 0; p < pixels; ++p) {
      const std::uint32_t pixel = first_pixel + p;
      const double px = pixel % width, py = pixel / width;
      std::set<std::pair<int, int>> cells;
      for (int k = 0; k < spp; ++k) {
        const std::uint32_t i = p * spp + k;
        INFO("spp " << spp << ", pixel " << pixel << ", sample " << k);
        const dev::Ray& r = rays[i];
        CHECK(r.sample == i);
        const auto [x, y] = contract_camera(scene, width, height).image_point(vec_of(r.dir));
        const double u = (x - px) * grid.u, v = (y - py) * grid.v;  // in cells
        REQUIRE(x >= px - 1e-6);
        REQUIRE(x <= px + 1 + 1e-6);
        REQUIRE(y >= py - 1e-6);
        REQUIRE(y <= py + 1 + 1e-6);
        cells.insert({static_cast<int>(std::floor(u)), static_cast<int>(std::floor(v))});
        if (std::fabs(u - std::floor(u) - 0.5) > 1e-3) jittered = true;
      }
      CHECK(cells.size() == static_cast<std::size_t>(spp));
    }
    CHECK(jittered);
  }
}

TEST_CASE("generate: every pixel gets its own jitter", "[generate]") {
  // 300 pixels: a jitter that repeated across pixels (a pattern) would show as equal offsets.
  const Scene scene = camera_scene(kEye, kOrigin, kUp, 60);
  const int width = 100, height = 3, spp = 4;
  const dev::Camera cam = make_camera(scene, image_options(width, height, spp, 5));
  const std::vector<dev::Ray> rays = generate(cam, 0, width * height * spp);
  std::set<std::pair<long, long>> offsets;  // sample 0's place in its pixel, in 1e-6 pixels
  for (int p = 0; p < width * height; ++p) {
    const auto [x, y] = contract_camera(scene, width, height).image_point(vec_of(rays[p * spp].dir));
    offsets.insert({std::lround((x - p % width) * 1e6), std::lround((y - p / width) * 1e6)});
  }
  CHECK(offsets.size() == static_cast<std::size_t>(width * height));
}

TEST_CASE("generate: jitter depends only on pixel, sample and seed", "[generate]") {
  const Scene scene = camera_scene(kEye, kOrigin, kUp, 60);
  const int spp = 4;
  const std::uint32_t pixels = 35;
  const dev::Camera cam = make_camera(scene, image_options(7, 5, spp, 9));
  const std::vector<dev::Ray> whole = generate(cam, 0, pixels * spp);

  SECTION("the same pixels in another wave get the same rays") {
    const std::uint32_t first = 9, count = 11;
    const std::vector<dev::Ray> part = generate(cam, first, count * spp);
    for (std::uint32_t i = 0; i < count * spp; ++i) {
      INFO("wave ray " << i);
      CHECK(test::same_bits(part[i].dir, whole[first * spp + i].dir));
      CHECK(part[i].path == whole[first * spp + i].path);
    }
  }
  SECTION("a round of each pixel's samples gets those samples' rays") {
    const std::uint32_t first_sample = 1, round = 2;  // samples 1 and 2 of 0..3
    const std::vector<dev::Ray> part = generate(cam, 0, pixels * round, first_sample, round);
    for (std::uint32_t p = 0; p < pixels; ++p)
      for (std::uint32_t k = 0; k < round; ++k) {
        INFO("pixel " << p << ", sample " << first_sample + k);
        const dev::Ray& r = part[p * round + k];
        const dev::Ray& w = whole[p * spp + first_sample + k];
        CHECK(r.sample == p * round + k);  // its place in the wave
        CHECK(test::same_bits(r.dir, w.dir));
        CHECK(r.path == w.path);
      }
  }
  SECTION("a second launch repeats every bit") {
    const std::vector<dev::Ray> again = generate(cam, 0, pixels * spp);
    for (std::uint32_t i = 0; i < pixels * spp; ++i) CHECK(test::same_bits(again[i].dir, whole[i].dir));
  }
  SECTION("another seed moves every sample") {
    dev::Camera reseeded = cam;
    reseeded.seed = 10;
    const std::vector<dev::Ray> other = generate(reseeded, 0, pixels * spp);
    std::size_t moved = 0;
    for (std::uint32_t i = 0; i < pixels * spp; ++i)
      moved += !test::same_bits(other[i].dir, whole[i].dir) && other[i].path != whole[i].path;
    CHECK(moved == pixels * spp);
  }
}

TEST_CASE("generate: a thin lens's rays leave its disc towards where the pinhole's meet the "
          "plane in focus, spread evenly over the disc",
          "[generate][lens]") {
  const Vec3 eye(1, 2, 6), lookat(0, 0.5, 0);
  const double radius = 0.3, focus = 4;
  Scene scene = camera_scene(eye, lookat, kUp, 50);
  Scene pinhole = scene;
  scene.camera.lens_radius = radius;
  scene.camera.focus_distance = focus;
  // The contract's basis, computed here: F the view, R = F x up, U = R x F.
  const Vec3 f = normalize(lookat - eye), r = normalize(cross(f, kUp)), u = cross(r, f);
  const int width = 9, height = 7, spp = 16;
  const std::uint32_t count = width * height * spp;
  for (const RenderMode mode : {RenderMode::Trace, RenderMode::Path}) {
    INFO((mode == RenderMode::Path ? "path mode's Sobol samples" : "the stratified samples"));
    RenderOptions options = image_options(width, height, spp, 7);
    options.mode = mode;
    const dev::Camera lens_camera = make_camera(scene, options);
    CHECK(lens_camera.thin_lens == 1);
    const std::vector<dev::Ray> rays = generate(lens_camera, 0, count);
    const std::vector<dev::Ray> pinhole_rays = generate(make_camera(pinhole, options), 0, count);
    // Equal-area cells of the disc: 4 rings (radii sqrt(k / 4)) by 4 quadrants.
    std::vector<int> cells(16, 0);
    for (std::uint32_t i = 0; i < count; ++i) {
      INFO("ray " << i);
      const Vec3 origin = vec_of(rays[i].origin), dir = vec_of(rays[i].dir);
      const Vec3 off = origin - eye;
      CHECK(std::fabs(dot(off, f)) < 1e-5);
      REQUIRE(length(off) <= radius * (1 + 1e-5));
      const Vec3 pinhole_dir = vec_of(pinhole_rays[i].dir);
      const Vec3 in_focus = eye + pinhole_dir * (focus / dot(pinhole_dir, f));
      const Vec3 reached = origin + dir * ((focus - dot(off, f)) / dot(dir, f));
      CHECK_NEAR_VEC(reached, in_focus, 2e-5 * focus);
      const double x = dot(off, r) / radius, y = dot(off, u) / radius;
      const int ring = std::min(3, static_cast<int>(4 * (x * x + y * y)));
      const int quadrant = (x >= 0 ? 0 : 1) + (y >= 0 ? 0 : 2);
      ++cells[ring * 4 + quadrant];
    }
    double chi2 = 0;
    const double expected = count / 16.0;
    for (int c : cells) chi2 += (c - expected) * (c - expected) / expected;
    INFO("chi-square " << chi2 << " over 16 equal-area cells");
    CHECK(chi2 < 37.7);  // 15 degrees of freedom, p = 0.001
  }
  Scene zero = scene;
  zero.camera.lens_radius = 0;
  CHECK(make_camera(zero, image_options(width, height, spp)).thin_lens == 0);
}
