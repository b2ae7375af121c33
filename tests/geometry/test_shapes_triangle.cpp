// intersect_triangle and triangle_normal on the device: hand-computed cases, random triangles
// against the host reference, and rays through the shared edges and vertices of a mesh.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "test_shapes_kernel.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

const std::vector<Vec3> kUnitTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

DeviceHit cast_one(const std::vector<Vec3>& triangle, const Mat4& m, const WorldRay& ray) {
  return cast_triangles(triangle, 1, 1, {m}, {ray})[0];
}

void expect_hit(const Mat4& m, const WorldRay& ray, double t, double u, double v,
                const Vec3& normal) {
  const DeviceHit got = cast_one(kUnitTriangle, m, ray);
  check_hit(got, t, normal);
  CHECK(got.u == Approx(u).margin(1e-6));
  CHECK(got.v == Approx(v).margin(1e-6));
}

void expect_miss(const WorldRay& ray) {
  const DeviceHit got = cast_one(kUnitTriangle, Mat4::identity(), ray);
  check_miss(got, ray);
  CHECK(got.u == -7);
  CHECK(got.v == -7);
}

}  // namespace

TEST_CASE("triangle: hand-computed hits and misses", "[shapes][triangle]") {
  const Mat4 identity;
  expect_hit(identity, {{0.25, 0.5, 1}, {0, 0, -1}}, 1, 0.25, 0.5, {0, 0, 1});
  // The back face is hit too, and the geometric normal is not flipped.
  expect_hit(identity, {{0.25, 0.5, -1}, {0, 0, 2}}, 0.5, 0.25, 0.5, {0, 0, 1});
  // Through a vertex and an edge: the closed triangle is hit.
  expect_hit(identity, {{1, 0, 1}, {0, 0, -1}}, 1, 1, 0, {0, 0, 1});
  expect_hit(identity, {{0.5, 0.5, 1}, {0, 0, -1}}, 1, 0.5, 0.5, {0, 0, 1});
  expect_hit(identity, {{-1, 0.5, 1}, {1, 0, -1}}, 1, 0, 0.5, {0, 0, 1});
  expect_miss({{0.6, 0.6, 1}, {0, 0, -1}});
  expect_miss({{-0.01, 0.5, 1}, {0, 0, -1}});
  // Behind the origin, beyond tmax, and within the triangle's plane.
  expect_miss({{0.25, 0.25, 1}, {0, 0, 1}});
  expect_miss({{0.25, 0.25, 1}, {0, 0, -1}, 1e-4, 0.99});
  expect_miss({{0.25, 0.25, 1}, {0, 0, -1}, 1.01, kUnbounded});
  expect_miss({{-1, 0.2, 0}, {1, 0, 0}});
}

TEST_CASE("triangle: placed by transforms", "[shapes][triangle]") {
  const Mat4 moved = Mat4::translate({0, 0, -3}) * Mat4::scale({2, 2, 2});
  expect_hit(moved, {{0.5, 1, 0}, {0, 0, -1}}, 3, 0.25, 0.5, {0, 0, 1});
  // rotatey 90 maps +z to +x: the front face now looks along +x.
  expect_hit(Mat4::rotate(90, {0, 1, 0}), {{3, 0.5, -0.25}, {-1, 0, 0}}, 3, 0.25, 0.5, {1, 0, 0});
  // Mirrored in x the world vertices run clockwise, and (M^-1)^T keeps the normal at +z.
  expect_hit(Mat4::scale({-1, 1, 1}), {{-0.25, 0.5, 1}, {0, 0, -1}}, 1, 0.25, 0.5, {0, 0, 1});
}

TEST_CASE("triangle_normal faces the side from which the vertices run counter-clockwise",
          "[shapes][triangle]") {
  // Seen from +y, (0,0,0) -> (0,0,2) -> (3,0,0) turns counter-clockwise (z towards x).
  const std::vector<Vec3> tri = {{0, 0, 0}, {0, 0, 2}, {3, 0, 0}};
  check_hit(cast_one(tri, Mat4::scale({1, 4, 1}), {{0.5, 5, 0.5}, {0, -1, 0}}), 5, {0, 1, 0});
  const std::vector<Vec3> reversed = {{0, 0, 0}, {3, 0, 0}, {0, 0, 2}};
  check_hit(cast_one(reversed, Mat4::identity(), {{0.5, 5, 0.5}, {0, -1, 0}}), 5, {0, -1, 0});
}

TEST_CASE("triangles agree with the host reference on random rays", "[shapes][triangle][random]") {
  std::mt19937 rng(77);
  const auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  const std::vector<Mat4> transforms = {
      Mat4::identity(), Mat4::translate({1, -2, 0.5}) * Mat4::scale({0.5, 3, 1.5}),
      Mat4::rotate(140, {-1, 0.4, 2}), Mat4::rotate(-30, {0, 1, 1}) * Mat4::scale({1, 1, -2})};
  std::vector<Vec3> vertices;
  std::vector<Mat4> placed;
  std::vector<WorldRay> rays;
  std::vector<ReferenceHit> expected;
  while (rays.size() < 1000) {
    const Vec3 v0{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    const Vec3 v1{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    const Vec3 v2{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    const Mat4& m = transforms[rays.size() % transforms.size()];
    const double a = uniform(-0.3, 1.1), b = uniform(-0.3, 1.1), speed = uniform(0.2, 2);
    // Skip targets within a hair of an edge, and planes within a hair of tmax.
    const double edge = std::min({a, b, 1 - a - b});
    if (std::abs(edge) < 1e-3) continue;
    const Vec3 target = m.transform_point(v0 + a * (v1 - v0) + b * (v2 - v0));
    WorldRay ray;
    ray.origin = round_to_float(m.transform_point(Vec3{uniform(-4, 4), uniform(-4, 4), uniform(-4, 4)}));
    ray.dir = round_to_float((target - ray.origin) * speed);
    ray.tmax = uniform(0, 1) < 0.5 ? kUnbounded : static_cast<float>(uniform(0.3, 1.5));
    if (std::abs(1 / speed - ray.tmax) < 1e-3) continue;
    const ReferenceHit hit = reference_triangle(v0, v1, v2, m, ray);
    vertices.insert(vertices.end(), {v0, v1, v2});
    placed.push_back(m);
    rays.push_back(ray);
    expected.push_back(hit);
  }
  const std::vector<DeviceHit> got = cast_triangles(vertices, 1, 1, placed, rays);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    INFO("ray " << i << " expected hit " << expected[i].hit << " t " << expected[i].t);
    REQUIRE(got[i].hit == expected[i].hit);
    if (!got[i].hit) continue;
    CHECK(got[i].t == Approx(expected[i].t).epsilon(1e-4));
    CHECK(got[i].u == Approx(expected[i].u).margin(1e-4));
    CHECK(got[i].v == Approx(expected[i].v).margin(1e-4));
    CHECK(length(got[i].normal - expected[i].normal) < 1e-4);
  }
}

// A closed mesh must not let rays slip between its triangles: an octahedron split into 8 x 16
// triangles (each face a fan about its centre), shot at exact shared vertices and at points of
// shared edges from every side.
TEST_CASE("rays through shared edges and vertices hit the mesh", "[shapes][triangle]") {
  std::vector<Vec3> mesh;
  const Vec3 corners[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<Vec3> edge_points;
  for (const int x : {0, 1})
    for (const int y : {2, 3})
      for (const int z : {4, 5}) {
        const Vec3 a = corners[x], b = corners[y], c = corners[z];
        const Vec3 centre = (a + b + c) / 3;
        const Vec3 ring[3] = {a, b, c};
        for (int k = 0; k < 3; ++k) {
          mesh.insert(mesh.end(), {centre, ring[k], ring[(k + 1) % 3]});
          edge_points.push_back(centre);
          edge_points.push_back(ring[k]);
          edge_points.push_back(centre + 0.37 * (ring[k] - centre));
          edge_points.push_back(ring[k] + 0.61 * (ring[(k + 1) % 3] - ring[k]));
        }
      }
  const int count = static_cast<int>(mesh.size() / 3);
  const Mat4 m = Mat4::translate({0.3, -0.2, 0.1}) * Mat4::rotate(33, {1, -2, 0.7}) *
                 Mat4::scale({1.7, 0.9, 1.3});
  // From outside, close to the radial direction, so that every ray enters the octahedron at
  // its target (even at a corner) at t = 1.
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0, 0.3);
  std::vector<WorldRay> rays;
  for (int pass = 0; pass < 20; ++pass)
    for (const Vec3& p : edge_points) {
      const Vec3 wobble = normalize(Vec3{normal(rng), normal(rng), normal(rng)}) * uniform(rng);
      const Vec3 from = m.transform_point(p + 3 * normalize(normalize(p) + wobble));
      const Vec3 origin = round_to_float(from);
      rays.push_back({origin, round_to_float(m.transform_point(p) - origin)});
    }
  const std::vector<DeviceHit> got =
      cast_triangles(mesh, count, 0, std::vector<Mat4>(rays.size(), m), rays);
  int missed = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (!got[i].hit) ++missed;
    if (got[i].hit) CHECK(got[i].t == Approx(1).margin(1e-4));
  }
  CHECK(missed == 0);
}
