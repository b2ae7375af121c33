// shade (kernels/shade.cl) launched alone on hand-made rays and hits, checked against the
// contract's Whitted terms computed here in double:
//   ambient  ka * La * C
//   light    kd * Ld * C * (N.L) + ks * Ld * max(0, R.V)^n  where N.L > 0, R = L mirrored about N
//   all of it times (1 - kr - kt) and the ray's weight.
// Most cases hit the point P = (0, 0, 0) of the plane y = 0 (normal +y) with a ray that left
// (0, 3, 4) along (0, -0.6, -0.8) and travelled t = 5.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "cl_fixture.hpp"
#include "render/frame_setup.hpp"
#include "render/stage_args.hpp"
#include "shared/ray.h"
#include "test_vectors.hpp"

using namespace clrt;
using test::f4_of;
using test::vec_of;
using test::set_triple;

namespace {

const Vec3 kP{0, 0, 0};
const Vec3 kUpNormal{0, 1, 0};
const Vec3 kAbove{0, 3, 4};
const Vec3 kDown{0, -0.6, -0.8};  // from kAbove to kP in t = 5
const double kT = 5;
constexpr double kEps = 1e-4;
constexpr double kTolerance = 2e-6;

Vec3 mul(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

// The contract's term of one light sample of colour ld seen along unit l (towards the light).
Vec3 light_term(const MaterialSpec& m, const Vec3& n, const Vec3& v, const Vec3& l, const Vec3& ld) {
  const double nl = dot(n, l);
  if (nl <= 0) return {};
  const Vec3 r = n * (2 * nl) - l;
  const double highlight = std::pow(std::max(0.0, dot(r, v)), m.shininess);
  return mul(ld, m.color) * (m.kd * nl) + ld * (m.ks * highlight);
}

MaterialSpec material(const Vec3& color, double ka, double kd, double ks, double n, double kr = 0,
                      double kt = 0, double ior = 1) {
  MaterialSpec m;
  m.color = color;
  m.ka = ka;
  m.kd = kd;
  m.ks = ks;
  m.shininess = n;
  m.kr = kr;
  m.kt = kt;
  m.ior = ior;
  return m;
}

LightSpec light(const std::string& kind, const Vec3& colour) {
  LightSpec l;
  l.kind = kind;
  l.color = colour;
  return l;
}

LightSpec ambient(const Vec3& colour) { return light("ambient", colour); }

LightSpec point(const Vec3& colour, const Vec3& position) {
  LightSpec l = light("point", colour);
  l.position = position;
  return l;
}

LightSpec directional(const Vec3& colour, const Vec3& travel) {
  LightSpec l = light("directional", colour);
  l.direction = travel;
  return l;
}

LightSpec spot(const Vec3& colour, const Vec3& position, const Vec3& axis, double angle, double exp) {
  LightSpec l = light("spot", colour);
  l.position = position;
  l.direction = axis;
  l.angle_degrees = angle;
  l.exponent = exp;
  return l;
}

LightSpec area(const Vec3& colour, const Vec3& corner, const Vec3& u, const Vec3& v, int samples) {
  LightSpec l = light("area", colour);
  l.position = corner;
  l.edge_u = u;
  l.edge_v = v;
  l.samples = samples;
  return l;
}

dev::Ray make_ray(const Vec3& origin, const Vec3& dir, const Vec3& weight = {1, 1, 1},
                  std::uint32_t depth = 0, std::uint32_t sample = 0, std::uint32_t path = 0x1234u) {
  dev::Ray r{};
  set_triple(r.origin, origin);
  r.radiance_scale = 1;
  set_triple(r.dir, dir);
  set_triple(r.weight, weight);
  r.sample = sample;
  r.depth_kind = CLRT_DEPTH_KIND(depth, depth == 0 ? CLRT_RAY_CAMERA : CLRT_RAY_REFLECTION);
  r.time = 0.375f;  // which children and shadow rays keep
  r.path = path;
  return r;
}

dev::Hit make_hit(const Vec3& geometric_normal, double t, std::uint32_t material_index,
                  const Vec3& shading_normal) {
  dev::Hit h{};
  h.geometric_normal = f4_of(geometric_normal, t);
  h.shading_normal = f4_of(shading_normal);
  h.instance = 0;
  h.material = material_index;
  return h;
}

dev::Hit make_hit(const Vec3& normal, double t, std::uint32_t material_index = 0) {
  return make_hit(normal, t, material_index, normal);
}

dev::Hit miss() {
  dev::Hit h{};
  h.instance = CLRT_NO_HIT;
  return h;
}

// What one shade launch is given: the scene supplies materials, lights and background, turned
// into device records by frame_setup as the renderer does.
struct ShadeInput {
  Scene scene;
  RenderOptions options;
  std::vector<dev::Ray> rays;
  std::vector<dev::Hit> hits;
};

ShadeInput input(const std::vector<MaterialSpec>& materials, const std::vector<LightSpec>& lights,
                 RenderMode mode = RenderMode::Trace) {
  ShadeInput in;
  in.scene.materials = materials;
  in.scene.lights = lights;
  in.scene.background = {0.1, 0.2, 0.3};
  in.options.mode = mode;
  in.options.max_depth = 5;
  return in;
}

struct ShadeOutput {
  std::uint32_t slots = 0;  // shadow slots per ray
  std::vector<dev::f4> colour;
  std::vector<dev::ShadowRay> shadows;
  std::vector<std::uint32_t> shadow_flags;
  std::vector<dev::Ray> spawns;
  std::vector<std::uint32_t> spawn_flags;

  const dev::ShadowRay& shadow(std::uint32_t local, std::uint32_t s) const {
    return shadows[local * slots + s];
  }
  std::uint32_t shadow_flag(std::uint32_t local, std::uint32_t s) const {
    return shadow_flags[local * slots + s];
  }
};

constexpr std::uint32_t kStaleFlag = 0xabu;  // what the flag buffers hold before the launch
const dev::f4 kStaleColour{-7, -7, -7, -7};

// Shades rays [first, first + count) (all of them by default). Flag and colour buffers start
// stale, so the test sees what the kernel wrote.
ShadeOutput shade(const ShadeInput& in, std::uint32_t first = 0, std::uint32_t count = ~0u) {
  const std::uint32_t n = static_cast<std::uint32_t>(in.rays.size());
  if (count == ~0u) count = n - first;
  const dev::RenderParams params = make_params(in.scene, in.options);
  ShadeOutput out;
  out.slots = params.shadow_samples;
  const std::size_t slot_count = std::max<std::size_t>(1, std::size_t{count} * out.slots);

  std::vector<dev::Light> light_table = make_lights(in.scene);
  if (light_table.empty()) light_table.resize(1);  // a buffer must not be empty
  ShadeArgs args;
  args.in.params = test::upload(std::vector<dev::RenderParams>{params});
  args.in.materials = test::upload(make_materials(in.scene));
  const TextureTable textures = make_texture_table(in.scene);
  args.in.textures = test::upload(textures.records);
  args.in.texels = test::upload(std::vector<cl_uint>(textures.texels.begin(), textures.texels.end()));
  args.in.lights = test::upload(light_table);
  args.in.rays = test::upload(in.rays);
  args.in.hits = test::upload(in.hits);
  args.first = first;
  args.count = count;
  args.out.colour = test::upload(std::vector<dev::f4>(n, kStaleColour));
  args.out.shadow_slots = test::upload(std::vector<dev::ShadowRay>(slot_count));
  args.out.shadow_flags = test::upload(std::vector<cl_uint>(slot_count, kStaleFlag));
  args.out.spawn_slots = test::upload(std::vector<dev::Ray>(2 * n));
  args.out.spawn_flags = test::upload(std::vector<cl_uint>(2 * n, kStaleFlag));
  test::run(test::renderer_program(in.options.mode), args, count);

  out.colour = test::download(args.out.colour, n);
  out.shadows = test::download(args.out.shadow_slots, slot_count);
  out.shadow_flags = test::download(args.out.shadow_flags, slot_count);
  out.spawns = test::download(args.out.spawn_slots, 2 * n);
  out.spawn_flags = test::download(args.out.spawn_flags, 2 * n);
  return out;
}

// The standard hit: the plane's point P seen from kAbove, its unit normal +y.
ShadeInput standard_hit(const std::vector<MaterialSpec>& materials,
                        const std::vector<LightSpec>& lights, RenderMode mode = RenderMode::Trace,
                        const Vec3& weight = {1, 1, 1}) {
  ShadeInput in = input(materials, lights, mode);
  in.rays = {make_ray(kAbove, kDown, weight)};
  in.hits = {make_hit(kUpNormal, kT)};
  return in;
}

const MaterialSpec kPlastic = material({0.8, 0.5, 0.2}, 0.3, 0.6, 0.4, 8);
const Vec3 kAmbient{0.2, 0.3, 0.4};
const Vec3 kV = -kDown;  // towards the viewer

// Lights seen from P: a point light near the mirror direction of the view (a bright highlight),
// a directional light, a spot with P inside its 30 degree cone (S.D = 3 / sqrt(10), exponent 2),
// a spot with P outside its 15 degree cone, and a point light below the plane (N.L < 0).
const Vec3 kPointPos{1, 3, -4};
const Vec3 kTravel{1, -2, 0.5};
const Vec3 kSpotPos{1, 3, 0};
const Vec3 kBelowPos{0, -2, 0.5};
std::vector<LightSpec> mixed_lights() {
  return {ambient({0.15, 0.2, 0.3}),
          point({0.9, 0.8, 0.7}, kPointPos),
          directional({0.3, 0.4, 0.5}, kTravel),
          spot({1, 1, 1}, kSpotPos, {0, -2, 0}, 30, 2),
          ambient({0.05, 0.1, 0.1}),
          spot({1, 1, 1}, kSpotPos, {0, -1, 0}, 15, 0),
          point({1, 1, 1}, kBelowPos)};
}

// The terms of mixed_lights() at P, by hand, in their slot order; zero where the light cannot
// contribute. `share` is the weight times (1 - kr - kt).
std::vector<Vec3> mixed_terms(const MaterialSpec& m, double share) {
  const double spot_factor = std::pow(3 / std::sqrt(10.0), 2);  // (S.D)^2 = 0.9
  return {light_term(m, kUpNormal, kV, normalize(kPointPos - kP), {0.9, 0.8, 0.7}) * share,
          light_term(m, kUpNormal, kV, normalize(-kTravel), {0.3, 0.4, 0.5}) * share,
          light_term(m, kUpNormal, kV, normalize(kSpotPos - kP), Vec3{1, 1, 1} * spot_factor) * share,
          Vec3{},
          Vec3{}};
}

Vec3 ambient_term(const MaterialSpec& m, const Vec3& la, double share) {
  return mul(la, m.color) * (m.ka * share);
}

}  // namespace

TEST_CASE("shade: a miss is the weight times the background", "[shade]") {
  for (RenderMode mode : {RenderMode::Trace, RenderMode::Cast}) {
    ShadeInput in = input({kPlastic}, mixed_lights(), mode);
    in.rays = {make_ray(kAbove, kDown, {0.5, 0.25, 1})};
    in.hits = {miss()};
    const ShadeOutput out = shade(in);
    CHECK_NEAR_VEC(vec_of(out.colour[0]), Vec3(0.05, 0.05, 0.3), kTolerance);
    if (mode == RenderMode::Trace) {
      for (std::uint32_t s = 0; s < out.slots; ++s) CHECK(out.shadow_flag(0, s) == 0);
      CHECK(out.spawn_flags[0] == 0);
      CHECK(out.spawn_flags[1] == 0);
    }
  }
}

TEST_CASE("shade: trace mode colours a hit with the ambient term only", "[shade]") {
  const MaterialSpec m = material({0.8, 0.5, 0.2}, 0.3, 0.6, 0.4, 8, 0.2, 0.3, 1.5);
  const Vec3 weight{0.5, 1, 0.25};
  const ShadeOutput out = shade(standard_hit({m}, mixed_lights(), RenderMode::Trace, weight));
  // La = (0.15, 0.2, 0.3) + (0.05, 0.1, 0.1); share = 1 - 0.2 - 0.3.
  CHECK_NEAR_VEC(vec_of(out.colour[0]), mul(weight, ambient_term(m, {0.2, 0.3, 0.4}, 0.5)),
                 kTolerance);
}

TEST_CASE("shade: cast mode adds every light's term as if unblocked", "[shade]") {
  SECTION("a diffuse and specular material") {
    const ShadeOutput out = shade(standard_hit({kPlastic}, mixed_lights(), RenderMode::Cast));
    Vec3 expected = ambient_term(kPlastic, kAmbient, 1);
    for (const Vec3& term : mixed_terms(kPlastic, 1)) expected = expected + term;
    CHECK_NEAR_VEC(vec_of(out.colour[0]), expected, kTolerance);
  }
  SECTION("a reflective and transparent material keeps only the local share") {
    const MaterialSpec m = material({0.8, 0.5, 0.2}, 0.3, 0.6, 0.4, 8, 0.25, 0.5, 1.3);
    const Vec3 weight{0.5, 0.5, 2};
    const ShadeOutput out = shade(standard_hit({m}, mixed_lights(), RenderMode::Cast, weight));
    Vec3 expected = ambient_term(m, kAmbient, 0.25);
    for (const Vec3& term : mixed_terms(m, 0.25)) expected = expected + term;
    CHECK_NEAR_VEC(vec_of(out.colour[0]), mul(weight, expected), kTolerance);
  }
  SECTION("kr + kt above 1 leaves no local colour at all") {
    const MaterialSpec m = material({0.8, 0.5, 0.2}, 0.3, 0.6, 0.4, 8, 0.7, 0.6, 1.3);
    const ShadeOutput out = shade(standard_hit({m}, mixed_lights(), RenderMode::Cast));
    CHECK_NEAR_VEC(vec_of(out.colour[0]), Vec3(0, 0, 0), 0);
  }
}

TEST_CASE("shade: the highlight follows pow(), so max(0, R.V)^0 = 1", "[shade]") {
  // A light behind the viewer's side at a grazing height: N.L > 0 but R.V < 0.
  const Vec3 light_pos{0, 1, 4};
  const Vec3 l = normalize(light_pos - kP);
  REQUIRE(dot(kUpNormal * (2 * dot(kUpNormal, l)) - l, kV) < 0);
  const std::vector<LightSpec> lights = {point({1, 1, 1}, light_pos)};
  const double nl = dot(kUpNormal, l);
  const Vec3 c{0.8, 0.5, 0.2};

  const ShadeOutput flat = shade(standard_hit({material(c, 0, 0.6, 0.4, 0)}, lights, RenderMode::Cast));
  CHECK_NEAR_VEC(vec_of(flat.colour[0]), c * (0.6 * nl) + Vec3(0.4, 0.4, 0.4), kTolerance);

  const ShadeOutput sharp = shade(standard_hit({material(c, 0, 0.6, 0.4, 8)}, lights, RenderMode::Cast));
  CHECK_NEAR_VEC(vec_of(sharp.colour[0]), c * (0.6 * nl), kTolerance);
}

TEST_CASE("shade: without ks there is no highlight, even where its power would overflow", "[shade]") {
  // Point lights on the mirror direction of the view at many distances: R.V rounds to just above
  // 1 for some of them, where max(0, R.V)^n overflows for a large exponent, and 0 times that
  // infinity would be NaN. The contract's term is the diffuse one alone.
  const Vec3 mirror{0, 0.6, -0.8};
  std::vector<LightSpec> lights;
  for (int i = 0; i < 64; ++i) lights.push_back(point({0.01, 0.01, 0.01}, kP + mirror * (0.3 + 0.01 * i)));
  const MaterialSpec m = material({0.8, 0.5, 0.2}, 0, 0.6, 0, 1e12);
  const ShadeOutput out = shade(standard_hit({m}, lights, RenderMode::Cast));
  Vec3 expected{0, 0, 0};
  for (const LightSpec& l : lights) expected = expected + light_term(m, kUpNormal, kV, normalize(l.position - kP), l.color);
  CHECK_NEAR_VEC(vec_of(out.colour[0]), expected, kTolerance);
}

TEST_CASE("shade: trace mode writes one shadow ray per contributing light sample", "[shade]") {
  const Vec3 weight{1, 0.5, 0.25};
  const MaterialSpec m = material({0.8, 0.5, 0.2}, 0.3, 0.6, 0.4, 8, 0.1, 0, 1);
  const ShadeOutput out = shade(standard_hit({m}, mixed_lights(), RenderMode::Trace, weight));
  REQUIRE(out.slots == 5);
  const std::vector<Vec3> terms = mixed_terms(m, 0.9);
  const Vec3 origin = kP + kUpNormal * kEps;  // towards the lights, all above the plane
  const std::vector<Vec3> targets = {kPointPos, Vec3{}, kSpotPos};
  for (std::uint32_t s = 0; s < 3; ++s) {
    INFO("slot " << s);
    REQUIRE(out.shadow_flag(0, s) == 1);
    const dev::ShadowRay& sr = out.shadow(0, s);
    CHECK_NEAR_VEC(vec_of(sr.origin), origin, 1e-6);
    CHECK_NEAR_VEC(vec_of(sr.contribution), mul(weight, terms[s]), kTolerance);
    CHECK(sr.owner == 0);
    CHECK(sr.time == 0.375f);
    CHECK(length(vec_of(sr.dir)) == Approx(1).margin(1e-6));
    if (s == 1) {
      CHECK(std::isinf(sr.origin.w));
      CHECK_NEAR_VEC(vec_of(sr.dir), normalize(-kTravel), 1e-6);
    } else {
      CHECK(sr.origin.w == Approx(length(targets[s] - origin)).epsilon(1e-6));
      CHECK_NEAR_VEC(vec_of(sr.dir), normalize(targets[s] - origin), 1e-6);
    }
  }
  CHECK(out.shadow_flag(0, 3) == 0);  // outside the spot's cone
  CHECK(out.shadow_flag(0, 4) == 0);  // below the surface: N.L < 0
}

TEST_CASE("shade: no shadow ray and no term where N.L <= 0", "[shade]") {
  // A light in the surface's plane (N.L = 0 exactly) and one just below it (N.L = -0.1).
  const std::vector<LightSpec> lights = {point({1, 1, 1}, {5, 0, 0}),
                                         directional({1, 1, 1}, {-0.995, 0.0998, 0})};
  const ShadeOutput traced = shade(standard_hit({kPlastic}, lights));
  CHECK(traced.shadow_flag(0, 0) == 0);
  CHECK(traced.shadow_flag(0, 1) == 0);
  const ShadeOutput cast = shade(standard_hit({kPlastic}, lights, RenderMode::Cast));
  CHECK_NEAR_VEC(vec_of(cast.colour[0]), Vec3(0, 0, 0), 0);
}

TEST_CASE("shade: one chunk of the queue, count rays from first", "[shade]") {
  // Ray 1 hits the plane from above, ray 2 from below; rays 0 and 3 are outside the chunk.
  ShadeInput in = input({kPlastic}, {ambient(kAmbient), point({1, 1, 1}, {0, 5, 0}),
                                     point({0.5, 0.5, 0.5}, {0, -5, 0})});
  const Vec3 up_dir{0, 0.6, -0.8};
  in.rays = {make_ray(kAbove, kDown), make_ray(kAbove, kDown, {1, 1, 1}, 0, 1),
             make_ray(kP - up_dir * kT, up_dir, {1, 1, 1}, 0, 2), make_ray(kAbove, kDown)};
  in.hits = {make_hit(kUpNormal, kT), make_hit(kUpNormal, kT), make_hit(kUpNormal, kT),
             make_hit(kUpNormal, kT)};
  const ShadeOutput out = shade(in, 1, 2);
  REQUIRE(out.slots == 2);
  CHECK(test::same_bits(out.colour[0], kStaleColour));
  CHECK(test::same_bits(out.colour[3], kStaleColour));
  CHECK_NEAR_VEC(vec_of(out.colour[1]), ambient_term(kPlastic, kAmbient, 1), kTolerance);
  CHECK_NEAR_VEC(vec_of(out.colour[2]), ambient_term(kPlastic, kAmbient, 1), kTolerance);

  // Ray 1 (local 0) sees only the light above; ray 2 (local 1) sees the plane's back, its
  // normal flipped to -y, so only the light below, and leaves from below the plane.
  CHECK(out.shadow_flag(0, 0) == 1);
  CHECK(out.shadow_flag(0, 1) == 0);
  CHECK(out.shadow_flag(1, 0) == 0);
  REQUIRE(out.shadow_flag(1, 1) == 1);
  CHECK(out.shadow(0, 0).owner == 1);
  CHECK(out.shadow(1, 1).owner == 2);
  CHECK_NEAR_VEC(vec_of(out.shadow(0, 0).origin), Vec3(0, kEps, 0), 1e-6);
  CHECK_NEAR_VEC(vec_of(out.shadow(1, 1).origin), Vec3(0, -kEps, 0), 1e-6);
  const Vec3 down_normal{0, -1, 0};
  CHECK_NEAR_VEC(vec_of(out.shadow(1, 1).contribution),
                 light_term(kPlastic, down_normal, -up_dir, down_normal, Vec3(0.5, 0.5, 0.5)),
                 kTolerance);
  // Spawn slots are indexed by the queue position: 2i and 2i + 1.
  for (std::uint32_t i : {1u, 2u}) {
    CHECK(out.spawn_flags[2 * i] == 0);
    CHECK(out.spawn_flags[2 * i + 1] == 0);
  }
  CHECK(out.spawn_flags[0] == kStaleFlag);
  CHECK(out.spawn_flags[6] == kStaleFlag);
}

TEST_CASE("shade: a shading normal shades, the geometric normal offsets", "[shade]") {
  const Vec3 shading = normalize(Vec3{0.3, 1, 0});
  ShadeInput in = input({kPlastic}, {point({1, 1, 1}, {-2, 3, 1})});
  in.rays = {make_ray(kAbove, kDown)};
  in.hits = {make_hit(kUpNormal, kT, 0, shading)};
  const ShadeOutput out = shade(in);
  REQUIRE(out.shadow_flag(0, 0) == 1);
  const Vec3 l = normalize(Vec3{-2, 3, 1} - kP);
  CHECK_NEAR_VEC(vec_of(out.shadow(0, 0).contribution), light_term(kPlastic, shading, kV, l, {1, 1, 1}),
                 kTolerance);
  CHECK_NEAR_VEC(vec_of(out.shadow(0, 0).origin), Vec3(0, kEps, 0), 1e-6);
}

TEST_CASE("shade: area light samples are stratified point lights of a share each", "[shade]") {
  const Vec3 corner{-1, 2, -1}, u{2, 0, 0}, v{0, 0, 1.5};
  const Vec3 colour{0.8, 1.2, 0.4};
  const std::vector<LightSpec> lights = {point({0.2, 0.2, 0.2}, {3, 3, 3}),
                                         area(colour, corner, u, v, 6)};
  const ShadeOutput traced = shade(standard_hit({kPlastic}, lights));
  REQUIRE(traced.slots == 7);

  std::set<std::pair<int, int>> cells;
  Vec3 sum = light_term(kPlastic, kUpNormal, kV, normalize(Vec3{3, 3, 3}), {0.2, 0.2, 0.2});
  for (std::uint32_t s = 1; s < 7; ++s) {
    INFO("slot " << s);
    REQUIRE(traced.shadow_flag(0, s) == 1);
    const dev::ShadowRay& sr = traced.shadow(0, s);
    const Vec3 q = vec_of(sr.origin) + vec_of(sr.dir) * sr.origin.w;  // the sampled point
    const double a = dot(q - corner, u) / dot(u, u), b = dot(q - corner, v) / dot(v, v);
    CHECK(std::fabs(dot(q - corner, cross(u, v))) < 1e-5);  // on the parallelogram's plane
    REQUIRE(a >= -1e-6);
    REQUIRE(a <= 1 + 1e-6);
    REQUIRE(b >= -1e-6);
    REQUIRE(b <= 1 + 1e-6);
    cells.insert({static_cast<int>(std::floor(a * 3)), static_cast<int>(std::floor(b * 2))});
    const Vec3 term = light_term(kPlastic, kUpNormal, kV, normalize(q - kP), colour / 6);
    CHECK_NEAR_VEC(vec_of(sr.contribution), term, kTolerance);
    sum = sum + term;
  }
  CHECK(cells.size() == 6);  // 6 samples: a 3 x 2 grid, one sample per cell

  SECTION("cast mode sums the same samples") {
    ShadeInput in = standard_hit({kPlastic}, lights, RenderMode::Cast);
    CHECK_NEAR_VEC(vec_of(shade(in).colour[0]), sum, 1e-5);
  }
  SECTION("the same ray path gives the same samples, another path others") {
    const ShadeOutput again = shade(standard_hit({kPlastic}, lights));
    ShadeInput other = standard_hit({kPlastic}, lights);
    other.rays[0].path ^= 0x5555u;
    const ShadeOutput moved = shade(other);
    for (std::uint32_t s = 1; s < 7; ++s) {
      CHECK(test::same_bits(again.shadow(0, s).dir, traced.shadow(0, s).dir));
      CHECK_FALSE(test::same_bits(moved.shadow(0, s).dir, traced.shadow(0, s).dir));
    }
  }
}

namespace {

// Checks a spawned ray: its origin P offset by epsilon to `side`, its direction, weight and
// bookkeeping.
void check_child(const dev::Ray& child, const dev::Ray& parent, const Vec3& side, const Vec3& dir,
                 const Vec3& weight, std::uint32_t kind) {
  CHECK_NEAR_VEC(vec_of(child.origin), kP + side * kEps, 1e-6);
  CHECK_NEAR_VEC(vec_of(child.dir), dir, 1e-6);
  CHECK(length(vec_of(child.dir)) == Approx(1).margin(1e-6));
  CHECK_NEAR_VEC(vec_of(child.weight), weight, kTolerance);
  CHECK(CLRT_RAY_DEPTH(child) == CLRT_RAY_DEPTH(parent) + 1);
  CHECK(child.sample == parent.sample);
  CHECK(CLRT_RAY_KIND(child) == kind);
  CHECK(child.time == parent.time);
  CHECK(child.path != parent.path);
}

ShadeInput glass_hit(const MaterialSpec& m, const Vec3& dir, std::uint32_t depth = 1) {
  ShadeInput in = input({m}, {ambient(kAmbient), point({1, 1, 1}, {0, 5, 0})});
  in.rays = {make_ray(kP - dir * kT, dir, {0.5, 1, 0.8}, depth, 7, 0x9876u)};
  in.hits = {make_hit(kUpNormal, kT)};
  return in;
}

}  // namespace

TEST_CASE("shade: reflection and refraction rays", "[shade]") {
  const Vec3 w{0.5, 1, 0.8};
  SECTION("a mirror spawns the reflection with weight kr") {
    const ShadeInput in = glass_hit(material({1, 1, 1}, 0.1, 0.2, 0.3, 10, 0.3), kDown);
    const ShadeOutput out = shade(in);
    REQUIRE(out.spawn_flags[0] == 1);
    CHECK(out.spawn_flags[1] == 0);
    check_child(out.spawns[0], in.rays[0], kUpNormal, {0, 0.6, -0.8}, w * 0.3, CLRT_RAY_REFLECTION);
  }
  SECTION("entering glass: Snell with n1 = 1, n2 = ior, weight kt") {
    const ShadeInput in = glass_hit(material({1, 1, 1}, 0.1, 0.2, 0.3, 10, 0.1, 0.6, 1.5), kDown);
    const ShadeOutput out = shade(in);
    REQUIRE(out.spawn_flags[0] == 1);
    REQUIRE(out.spawn_flags[1] == 1);
    check_child(out.spawns[0], in.rays[0], kUpNormal, {0, 0.6, -0.8}, w * 0.1, CLRT_RAY_REFLECTION);
    const double sin_t = 0.8 / 1.5, cos_t = std::sqrt(1 - sin_t * sin_t);
    check_child(out.spawns[1], in.rays[0], -kUpNormal, {0, -cos_t, -sin_t}, w * 0.6,
                CLRT_RAY_REFRACTION);
    CHECK(out.spawns[0].path != out.spawns[1].path);
  }
  SECTION("leaving glass: n1 = ior, n2 = 1") {
    const Vec3 d{0, 0.8, -0.6};  // from inside, 36.87 degrees from the normal
    const ShadeInput in = glass_hit(material({1, 1, 1}, 0.1, 0.2, 0.3, 10, 0.1, 0.6, 1.5), d);
    const ShadeOutput out = shade(in);
    REQUIRE(out.spawn_flags[0] == 1);
    REQUIRE(out.spawn_flags[1] == 1);
    check_child(out.spawns[0], in.rays[0], -kUpNormal, {0, -0.8, -0.6}, w * 0.1,
                CLRT_RAY_REFLECTION);
    const double sin_t = 0.6 * 1.5, cos_t = std::sqrt(1 - sin_t * sin_t);
    check_child(out.spawns[1], in.rays[0], kUpNormal, {0, cos_t, -sin_t}, w * 0.6,
                CLRT_RAY_REFRACTION);
  }
  SECTION("total internal reflection: one reflection ray of weight kr + kt") {
    const Vec3 d{0, 0.6, -0.8};  // sin = 0.8 * 1.5 > 1
    for (double kr : {0.0, 0.1}) {
      INFO("kr " << kr);
      const ShadeInput in = glass_hit(material({1, 1, 1}, 0.1, 0.2, 0.3, 10, kr, 0.6, 1.5), d);
      const ShadeOutput out = shade(in);
      REQUIRE(out.spawn_flags[0] == 1);
      CHECK(out.spawn_flags[1] == 0);
      check_child(out.spawns[0], in.rays[0], -kUpNormal, {0, -0.6, -0.8}, w * (kr + 0.6),
                  CLRT_RAY_REFLECTION);
    }
  }
  SECTION("a material with kr = kt = 0 spawns nothing") {
    const ShadeOutput out = shade(glass_hit(kPlastic, kDown));
    CHECK(out.spawn_flags[0] == 0);
    CHECK(out.spawn_flags[1] == 0);
  }
}

TEST_CASE("shade: a ray at the maximum depth spawns nothing but is still lit", "[shade]") {
  const MaterialSpec glass = material({1, 1, 1}, 0.1, 0.2, 0.3, 10, 0.3, 0.5, 1.5);
  ShadeInput in = glass_hit(glass, kDown, 3);
  in.options.max_depth = 3;
  const ShadeOutput deepest = shade(in);
  CHECK(deepest.spawn_flags[0] == 0);
  CHECK(deepest.spawn_flags[1] == 0);
  CHECK(deepest.shadow_flag(0, 0) == 1);

  in.options.max_depth = 4;
  const ShadeOutput above = shade(in);
  CHECK(above.spawn_flags[0] == 1);
  CHECK(above.spawn_flags[1] == 1);
}
