// Path mode's area-light samples (kernels/render/lights/area.h, math/spherical_rectangle.h) on
// the device against the host: a rectangle's points drawn uniformly in the solid angle it
// subtends, by a chi-square test of the directions against 1 / (its solid angle) inside it,
// that solid angle computed on the host in double by another formula (two spherical triangles,
// Van Oosterom and Strackee); a path's crossing of the light claiming the density its sample
// did; and uniform points on the surface where the rectangle looks small, where it is no
// rectangle, and in the Whitted modes.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "cl_fixture.hpp"
#include "render/frame_setup.hpp"
#include "sphere_chi_square.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

// The same kernel built for path mode and for the Whitted modes.
const std::string kKernel = R"CL(
#include "render/lights.h"
#include "render/random.h"

/* Sample i of the light from p with an independent pair of numbers, and the light's crossing
 * by the ray from p along the sample's direction. */
__kernel void draw_light_samples(__global const Light* light, float4 p, uint count,
                                 __global float4* directions, __global float4* densities) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float2 u = (float2)(uniform_float(hash_u32(2u * i + 1u)), uniform_float(hash_u32(2u * i + 2u)));
  const LightSample s = sample_light(light, 0u, p.xyz, u);
  const LightCrossing c = light_crossing(light, p.xyz, s.to_light, 0.0f, INFINITY);
  directions[i] = (float4)(s.to_light, s.distance);
  densities[i] = (float4)(s.density, s.geometry, c.density, c.t);
}
)CL";

const std::string kPathKernel = "#define CLRT_TRANSPORT CLRT_MODE_PATH\n" + kKernel;

struct DrawLightSamplesArgs {
  static constexpr const char* kName = "draw_light_samples";
  Global<const dev::Light> light;
  dev::f4 p;
  cl_uint count = 0;
  Global<dev::f4> directions, densities;
  CLRT_KERNEL_ARGS(light, p, count, directions, densities)
};

struct Rectangle {
  V3 corner, u, v;
};

double norm(V3 a) { return std::sqrt(dot(a, a)); }

// The solid angle of triangle abc (vectors from the eye), Van Oosterom and Strackee.
double triangle_solid_angle(V3 a, V3 b, V3 c) {
  const double la = norm(a), lb = norm(b), lc = norm(c);
  const double numerator = std::fabs(dot(a, cross(b, c)));
  const double denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2 * std::atan2(numerator, denominator);
}

double solid_angle(const Rectangle& r, V3 p) {
  const V3 a = r.corner - p, b = a + r.u, c = a + r.u + r.v, d = a + r.v;
  return triangle_solid_angle(a, b, c) + triangle_solid_angle(a, c, d);
}

// Whether the ray from p along w meets the rectangle.
bool hits(const Rectangle& r, V3 p, V3 w) {
  const V3 n = cross(r.u, r.v);
  const double facing = dot(n, w);
  if (facing == 0) return false;
  const double t = dot(n, r.corner - p) / facing;
  if (t <= 0) return false;
  const V3 q = p + t * w - r.corner;
  const double a = dot(q, r.u) / dot(r.u, r.u), b = dot(q, r.v) / dot(r.v, r.v);
  return a >= 0 && a <= 1 && b >= 0 && b <= 1;
}

dev::f4 f4_of(V3 v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0};
}

std::vector<dev::Light> light_table(const Rectangle& r) {
  Scene scene;
  LightSpec spec;
  spec.kind = "area";
  spec.color = {1, 1, 1};
  spec.position = {r.corner.x, r.corner.y, r.corner.z};
  spec.edge_u = {r.u.x, r.u.y, r.u.z};
  spec.edge_v = {r.v.x, r.v.y, r.v.z};
  spec.samples = 1;
  scene.lights.push_back(spec);
  return make_lights(scene);
}

struct Draws {
  std::vector<dev::f4> directions, densities;
};

Draws draw(const std::string& kernel, const Rectangle& r, V3 p, std::size_t count) {
  const Global<dev::f4> directions = allocate<dev::f4>(count), densities = allocate<dev::f4>(count);
  run(test_program(kernel),
      DrawLightSamplesArgs{upload(light_table(r)), f4_of(p), static_cast<cl_uint>(count), directions, densities},
      count);
  return {download(directions, count), download(densities, count)};
}

std::size_t sample_count() {
  return device().device().platform().name() == "Oclgrind" ? 4000 : 200000;
}

// A 2 x 1.5 rectangle, tilted, and points it is drawn from: near its middle, off to a side and
// low, and behind it (lights shine from both faces).
const Rectangle kRectangle{{-1, 0.5, 2}, {2, 0, 0.3}, {0, 1.5, 0}};

}  // namespace

TEST_CASE("path mode draws a near rectangular light uniformly in the solid angle it subtends",
          "[kernels][path][lights]") {
  const V3 p = GENERATE(V3{0.1, 1.1, 1.2}, V3{-2.0, 0.2, 1.5}, V3{0.3, 1.0, 3.0});
  INFO("from (" << p.x << ", " << p.y << ", " << p.z << ")");
  const double omega = solid_angle(kRectangle, p);
  REQUIRE(omega > 1.0 / 64);
  const std::size_t count = sample_count();
  const Draws d = draw(kPathKernel, kRectangle, p, count);
  const V3 centre = kRectangle.corner + 0.5 * kRectangle.u + 0.5 * kRectangle.v;
  const Frame frame = frame_of(unit(centre - p));
  std::vector<double> observed(kZBins * kPhiBins, 0.0), expected(kZBins * kPhiBins, 0.0);
  int off_light = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const V3 w = unit(of(d.directions[i]));
    observed[static_cast<std::size_t>(bin_of(frame, w))] += 1;
    off_light += !hits(kRectangle, p, w);
    // Every sample claims density 1 / omega, and a path along it meets the light with the same.
    CHECK(d.densities[i].x == Approx(1 / omega).epsilon(2e-4));
    CHECK(d.densities[i].y == Approx(omega).epsilon(2e-4));
    CHECK(d.densities[i].z == Approx(d.densities[i].x).epsilon(1e-5));
  }
  CHECK(off_light <= static_cast<int>(count / 10000));  // only a rounding off an edge
  // The density integrated over the bins, finely: the light's edges cut through them.
  for_each_bin_point(frame, 256, [&](int bin, V3 w, double d_omega) {
    if (hits(kRectangle, p, w)) expected[static_cast<std::size_t>(bin)] += d_omega / omega * count;
  });
  chi2_test(observed, expected);
}

TEST_CASE("a light that looks small, a parallelogram, the Whitted modes and a point in the light's "
          "plane keep uniform points on the surface",
          "[kernels][path][lights]") {
  const auto area_density = [](const Rectangle& r, V3 w, double distance) {
    const V3 n = cross(r.u, r.v);
    return distance * distance / (std::fabs(dot(n, w)) / norm(n) * norm(n));
  };
  struct Case {
    const char* what;
    std::string kernel;
    Rectangle light;
    V3 p;
  };
  const Rectangle parallelogram{{-1, 0.5, 2}, {2, 0, 0.3}, {0.5, 1.5, 0}};
  for (const Case& c : {Case{"far", kPathKernel, kRectangle, V3{0, 1, -40}},
                        Case{"parallelogram", kPathKernel, parallelogram, V3{0.1, 1.1, 1.2}},
                        Case{"Whitted", kKernel, kRectangle, V3{0.1, 1.1, 1.2}}}) {
    INFO(c.what);
    const Draws d = draw(c.kernel, c.light, c.p, 64);
    for (std::size_t i = 0; i < 64; ++i) {
      const V3 w = of(d.directions[i]);
      const double expected = area_density(c.light, w, d.directions[i].w);
      CHECK(d.densities[i].x == Approx(expected).epsilon(1e-4));
      CHECK(d.densities[i].z == Approx(expected).epsilon(1e-4));
    }
  }
  // A point in the light's own plane, beside it: no solid angle to draw in, and no NaN.
  const V3 beside = kRectangle.corner + 1.5 * kRectangle.u + 0.5 * kRectangle.v;
  const Draws d = draw(kPathKernel, kRectangle, beside, 64);
  for (std::size_t i = 0; i < 64; ++i) {
    INFO("sample " << i);
    CHECK((std::isfinite(d.directions[i].x) && std::isfinite(d.directions[i].y) &&
           std::isfinite(d.directions[i].z) && d.directions[i].w > 0));
    CHECK(std::isfinite(d.densities[i].x));
  }
}
