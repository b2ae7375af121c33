// Path mode's glow light (kernels/render/lights/glow.h) on the device against the host: a
// glowing sphere and two glowing triangles, picked in proportion to their power (luminance times
// area) and sampled in the cone a sphere subtends and uniformly over a triangle's area. A
// chi-square test compares the sampled directions with the host's mixture of those densities,
// which the host works out in double from the scene alone, not from the emitter table. Every
// sample's claimed density must match the host's value for the surface its direction meets,
// and a path that hits that surface must claim the same density (glow_light_density). Surfaces
// seen from behind, and a sphere seen from inside, give nothing.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "cl_fixture.hpp"
#include "geometry/geometry_data.hpp"
#include "render/frame_setup.hpp"
#include "sphere_chi_square.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

const std::string kKernel = R"CL(
#define CLRT_TRANSPORT CLRT_MODE_PATH
#include "render/lights.h"
#include "render/random.h"

/* Sample i of the glow light from p, with an independent pair of numbers. */
__kernel void draw_glow_samples(__global const Light* lights, uint glow, float4 p, uint count,
                                __global float4* directions, __global float4* densities) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float2 u = (float2)(uniform_float(hash_u32(2u * i + 1u)), uniform_float(hash_u32(2u * i + 2u)));
  const LightSample s = sample_light(&lights[glow], 0u, p.xyz, u);
  directions[i] = (float4)(s.to_light, s.distance);
  densities[i] = (float4)(s.density, s.geometry, s.intensity.x + s.intensity.y + s.intensity.z, 0.0f);
}

/* The density a path from p claims for the glowing point it met: surface (its Hit.glow) at
 * distance t, turned by cos_light to the path, emitting `emission`. */
__kernel void glow_hit_densities(__global const Light* lights, uint glow, float4 p, uint count,
                                 __global const uint* surfaces, __global const float4* hits,
                                 __global float* densities) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float4 h = hits[i];
  densities[i] = glow_light_density(&lights[glow], surfaces[i], p.xyz, h.x, h.y,
                                    (float3)(h.z, h.w, hits[count + i].x));
}
)CL";

struct DrawGlowSamplesArgs {
  static constexpr const char* kName = "draw_glow_samples";
  Global<const dev::Light> lights;
  cl_uint glow = 0;
  dev::f4 p;
  cl_uint count = 0;
  Global<dev::f4> directions, densities;
  CLRT_KERNEL_ARGS(lights, glow, p, count, directions, densities)
};

struct GlowHitDensitiesArgs {
  static constexpr const char* kName = "glow_hit_densities";
  Global<const dev::Light> lights;
  cl_uint glow = 0;
  dev::f4 p;
  cl_uint count = 0;
  Global<const cl_uint> surfaces;
  Global<const dev::f4> hits;
  Global<float> densities;
  CLRT_KERNEL_ARGS(lights, glow, p, count, surfaces, hits, densities)
};

double norm(V3 a) { return std::sqrt(dot(a, a)); }
double luminance(V3 c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }
Vec3 vec(V3 v) { return {v.x, v.y, v.z}; }

// The scene's glowing surfaces as the host sees them.
struct GlowSphere {
  V3 centre;
  double radius;
  V3 emission;
};
struct GlowTriangle {
  V3 a, b, c;  // counter-clockwise seen from the glowing side
  V3 emission;
};

const GlowSphere kSphere{{0.2, -0.1, 3}, 0.8, {2, 1, 0.5}};
const GlowTriangle kTriangles[2] = {
    {{-2.5, -0.5, 2.5}, {-2.0, 0.5, 2.5}, {-1.5, -0.5, 2.5}, {0.3, 0.6, 1.0}},
    {{1.5, -0.6, 2.2}, {2.1, 0.7, 2.6}, {2.6, -0.4, 2.4}, {1, 1, 1}}};

// What a direction from p meets of one surface: nothing, or its distance, the cosine at the
// surface (> 0 on the glowing side) and the density with which that surface's own sampling
// draws the direction.
struct Meeting {
  double t, cos_light, density;
};

std::optional<Meeting> meet_sphere(V3 p, V3 w) {
  const V3 to_centre = kSphere.centre - p;
  const double dist = norm(to_centre), r = kSphere.radius;
  const double cos_max = std::sqrt(1 - r * r / (dist * dist));
  if (dot(unit(to_centre), w) < cos_max) return std::nullopt;
  const double b = dot(to_centre, w), disc = b * b - (dist * dist - r * r);
  const double t = b - std::sqrt(std::max(0.0, disc));
  const V3 n = unit(p + t * w - kSphere.centre);
  return Meeting{t, -dot(n, w), 1 / (2 * kPi * (1 - cos_max))};
}

std::optional<Meeting> meet_triangle(const GlowTriangle& tri, V3 p, V3 w) {
  const V3 e1 = tri.b - tri.a, e2 = tri.c - tri.a, n = cross(e1, e2);
  const double facing = dot(n, w);
  if (facing == 0) return std::nullopt;
  const double t = dot(n, tri.a - p) / facing;
  if (t <= 0) return std::nullopt;
  const V3 q = p + t * w - tri.a;
  const double n2 = dot(n, n);
  const double u = dot(cross(q, e2), n) / n2, v = dot(cross(e1, q), n) / n2;
  if (u < 0 || v < 0 || u + v > 1) return std::nullopt;
  const double area = norm(n) / 2, cos_light = -facing / norm(n);
  return Meeting{t, cos_light, t * t / (std::fabs(cos_light) * area)};
}

// The chances of picking the sphere and each triangle: their shares of the power.
std::vector<double> picks() {
  const double r = kSphere.radius;
  std::vector<double> power = {luminance(kSphere.emission) * 4 * kPi * r * r};
  for (const GlowTriangle& tri : kTriangles)
    power.push_back(luminance(tri.emission) * norm(cross(tri.b - tri.a, tri.c - tri.a)) / 2);
  double total = 0;
  for (double x : power) total += x;
  for (double& x : power) x /= total;
  return power;
}

// The scene: the three glowing surfaces, and a glowing plane and an ellipsoid, which the glow
// light does not sample.
Scene glow_scene() {
  Scene scene;
  scene.materials.resize(1);
  const auto material = [&scene](V3 emission) {
    MaterialSpec m;
    m.emission = vec(emission);
    scene.materials.push_back(m);
    return static_cast<int>(scene.materials.size() - 1);
  };
  const Mat4 sphere = Mat4::translate(vec(kSphere.centre)) *
                      Mat4::rotate(30, {1, 2, 3}) * Mat4::scale({kSphere.radius, kSphere.radius, kSphere.radius});
  scene.instances.push_back(place_instance(ShapeKind::Sphere, sphere, material(kSphere.emission)));
  scene.instances.push_back(place_instance(ShapeKind::Plane, Mat4::translate({0, -3, 0}), material({5, 5, 5})));
  scene.instances.push_back(place_instance(ShapeKind::Sphere, Mat4::translate({0, 0, -5}) * Mat4::scale({1, 2, 1}),
                                           material({5, 5, 5})));
  for (const GlowTriangle& tri : kTriangles)
    scene.triangles.push_back({vec(tri.a), vec(tri.b), vec(tri.c), material(tri.emission)});
  return scene;
}

struct GlowTable {
  Global<const dev::Light> lights;
  cl_uint glow = 0;
};

GlowTable glow_table(const Scene& scene, std::size_t rows = 3) {  // the sphere and the two triangles
  const GeometryData geometry = build_geometry(scene);
  REQUIRE(geometry.emitters.size() == rows);
  RenderOptions options = RenderOptions::from_scene(scene);
  options.mode = RenderMode::Path;
  const FrameData frame = make_frame(scene, geometry, options);
  REQUIRE(frame.params.glow_light != CLRT_NO_LIGHT);
  const std::vector<unsigned char> bytes = light_table_bytes(frame, geometry);
  return {Global<const dev::Light>(device().allocate_copy(bytes.data(), bytes.size(), "light table")),
          frame.params.glow_light};
}

std::size_t sample_count() {
  return device().device().platform().name() == "Oclgrind" ? 4000 : 200000;
}

dev::f4 f4_of(V3 v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0};
}

struct Draws {
  std::vector<dev::f4> directions, densities;
};

Draws draw(const GlowTable& table, V3 p, std::size_t count) {
  const Global<dev::f4> directions = allocate<dev::f4>(count), densities = allocate<dev::f4>(count);
  run(test_program(kKernel),
      DrawGlowSamplesArgs{table.lights, table.glow, f4_of(p), static_cast<cl_uint>(count), directions, densities},
      count);
  return {download(directions, count), download(densities, count)};
}

}  // namespace

TEST_CASE("the glow light picks surfaces by power and draws spheres by cone and triangles by area",
          "[kernels][path][lights]") {
  const Scene scene = glow_scene();
  const GlowTable table = glow_table(scene);
  const V3 p{0.1, 0.2, 0.0};
  const std::size_t count = sample_count();
  const Draws d = draw(table, p, count);
  const std::vector<double> chance = picks();
  // The host's density of the mixture in direction w, and what each surface contributes to it.
  const auto meetings = [&](V3 w) {
    std::vector<std::optional<Meeting>> m = {meet_sphere(p, w)};
    for (const GlowTriangle& tri : kTriangles) m.push_back(meet_triangle(tri, p, w));
    return m;
  };
  const Frame frame = frame_of(V3{0, 0, 1});
  std::vector<double> observed(kZBins * kPhiBins, 0.0), expected(kZBins * kPhiBins, 0.0);
  std::vector<cl_uint> surfaces(count);
  std::vector<dev::f4> hits(2 * count);
  std::size_t met = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const V3 w = unit(of(d.directions[i]));
    observed[static_cast<std::size_t>(bin_of(frame, w))] += 1;
    const auto m = meetings(w);
    // The surfaces do not overlap as seen from p: a direction meets at most one of them.
    std::size_t which = m.size();
    for (std::size_t k = 0; k < m.size(); ++k)
      if (m[k]) which = k;
    surfaces[i] = which == 0 ? 0u : CLRT_GLOW_TRIANGLES;  // the sphere is the table's first row
    if (which == m.size()) continue;  // just off an edge, aimed a hair in front of the surface
    ++met;
    const Meeting& hit = *m[which];
    const double density = chance[which] * hit.density;
    INFO("sample " << i << " meets surface " << which);
    CHECK(d.densities[i].x == Approx(density).epsilon(1e-3));
    CHECK(d.densities[i].y == Approx(1 / density).epsilon(1e-3));
    CHECK(d.densities[i].z > 0);
    const V3 e = which == 0 ? kSphere.emission : kTriangles[which - 1].emission;
    hits[i] = dev::f4{static_cast<float>(hit.t), static_cast<float>(hit.cos_light), static_cast<float>(e.x),
                      static_cast<float>(e.y)};
    hits[count + i].x = static_cast<float>(e.z);
  }
  CHECK(count - met <= count / 1000);
  // A path along each direction meets the surface with the density the sample claimed.
  const Global<float> hit_densities = allocate<float>(count);
  run(test_program(kKernel),
      GlowHitDensitiesArgs{table.lights, table.glow, f4_of(p), static_cast<cl_uint>(count), upload(surfaces),
                           upload(hits), hit_densities},
      count);
  const std::vector<float> claimed = download(hit_densities, count);
  for (std::size_t i = 0; i < count; ++i) {
    if (hits[i].x == 0) continue;
    CHECK(claimed[i] == Approx(d.densities[i].x).epsilon(1e-3));
  }
  for_each_bin_point(frame, 128, [&](int bin, V3 w, double d_omega) {
    const auto m = meetings(w);
    for (std::size_t k = 0; k < m.size(); ++k)
      if (m[k]) expected[static_cast<std::size_t>(bin)] += chance[k] * m[k]->density * d_omega * count;
  });
  chi2_test(observed, expected);
}

TEST_CASE("the glow light brings nothing from a surface's back or from inside a sphere",
          "[kernels][path][lights]") {
  const Scene scene = glow_scene();
  const GlowTable table = glow_table(scene);
  const std::vector<double> chance = picks();
  // The chance that a sample from p brings nothing: that of the surfaces p sees from behind,
  // and of the sphere when p is inside it.
  const auto dark_chance = [&](V3 p) {
    double dark = norm(p - kSphere.centre) > kSphere.radius ? 0 : chance[0];
    for (std::size_t k = 0; k < 2; ++k) {
      const GlowTriangle& tri = kTriangles[k];
      if (dot(cross(tri.b - tri.a, tri.c - tri.a), p - tri.a) <= 0) dark += chance[k + 1];
    }
    return dark;
  };
  struct Case {
    const char* what;
    V3 p;
  };
  for (const Case& c : {Case{"behind the triangles", V3{0, 0, 4.5}},
                        Case{"inside the sphere", kSphere.centre + V3{0.1, 0.2, -0.6}}}) {
    INFO(c.what);
    const std::size_t count = 20000;
    const Draws d = draw(table, c.p, count);
    std::size_t dark = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const bool nothing = d.densities[i].y == 0;
      if (nothing) CHECK(d.densities[i].z == 0);
      dark += nothing;
    }
    // Binomial: 5 standard deviations.
    const double expected = dark_chance(c.p);
    INFO("nothing from " << dark << " of " << count << " samples, expected a share of " << expected);
    CHECK(expected > 0.05);
    CHECK(expected < 0.99);
    CHECK(std::fabs(static_cast<double>(dark) - expected * count) <= 5 * std::sqrt(count * expected * (1 - expected)));
  }
}

TEST_CASE("the glow light draws finite samples from a sphere of radius 1e-8 and a triangle at 1e10",
          "[kernels][path][lights]") {
  // The sphere is far smaller than the floats' spacing around the shading point, so the sampled
  // point is rounded by more than the radius; the triangle's normal (1e20 long) has a square
  // beyond the floats. Both used to give NaN or a zero-length normal.
  struct Case {
    const char* what;
    V3 p, centre;  // the shading point, and the surface's centre
    double radius;
    GlowTriangle triangle;
  };
  const GlowTriangle none{};
  const GlowTriangle far{{-1e10, -1e10, 3e10}, {0, 1e10, 3e10}, {1e10, -1e10, 3e10}, {1, 1, 1}};
  for (const Case& c : {Case{"a sphere of radius 1e-8", {0.1, 0.2, 0}, {0.2, -0.1, 1.5}, 1e-8, none},
                        Case{"a triangle at 1e10", {1e9, 0, 0}, (1.0 / 3) * (far.a + far.b + far.c), 0, far}}) {
    INFO(c.what);
    Scene scene;
    scene.materials.resize(2);
    scene.materials[1].emission = {1, 1, 1};
    if (c.radius > 0)
      scene.instances.push_back(place_instance(
          ShapeKind::Sphere, Mat4::translate(vec(c.centre)) * Mat4::scale({c.radius, c.radius, c.radius}), 1));
    else
      scene.triangles.push_back({vec(c.triangle.a), vec(c.triangle.b), vec(c.triangle.c), 1});
    const GlowTable table = glow_table(scene, 1);
    const std::size_t count = 4000;
    const Draws d = draw(table, c.p, count);
    const V3 towards = c.centre - c.p;
    const double dist = norm(towards);
    for (std::size_t i = 0; i < count; ++i) {
      const V3 w = of(d.directions[i]);
      INFO("sample " << i);
      REQUIRE(std::isfinite(d.densities[i].x));
      REQUIRE(std::isfinite(d.densities[i].y));
      REQUIRE(d.densities[i].z > 0);
      if (c.radius > 0) {
        // Every sample is the sphere's point, seen in the cone of the sphere's (1e-8) radius.
        CHECK(dot(w, unit(towards)) == Approx(1).epsilon(1e-6));
        CHECK(d.directions[i].w == Approx(dist).margin(2e-4));  // aimed 1e-4 in front of it
        // The only emitter: the sample's density is one over the cone's solid angle.
        const double solid_angle = kPi * c.radius * c.radius / (dist * dist);
        CHECK(d.densities[i].x == Approx(1 / solid_angle).epsilon(1e-3));
      } else {
        const std::optional<Meeting> m = meet_triangle(c.triangle, c.p, unit(w));
        REQUIRE(m);
        CHECK(d.densities[i].x == Approx(m->density).epsilon(1e-3));
        CHECK(d.densities[i].y == Approx(1 / m->density).epsilon(1e-3));
      }
    }
  }
}
