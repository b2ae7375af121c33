// What scene_closest_hit reports besides finding the hit: t, normals, materials, primitives;
// and that an instanced mesh is hit exactly like its triangles written out in world space.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "bvh_reference.hpp"
#include "bvh_test_device.hpp"
#include "bvh_test_scenes.hpp"
#include "geometry/geometry_data.hpp"

using namespace clrt;
using namespace clrt::bvhtest;

namespace {

Vec3 xyz(const dev::f4& v) { return {v.x, v.y, v.z}; }

dev::Hit closest(const Scene& scene, const TestRay& ray) {
  return device_closest_hits(build_geometry(scene), {ray}).at(0);
}

void check_near(const Vec3& got, const Vec3& want) {
  INFO("got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x << ", " << want.y
               << ", " << want.z << ")");
  CHECK(length(got - want) < 1e-4);
}

}  // namespace

TEST_CASE("a sphere hit reports t, the outward world normal and the instance's material", "[bvh][device]") {
  Scene scene;
  // An ellipsoid: radius 2 along x, 1 along y and z, centred at (0, 0, -5), material 3.
  scene.instances.push_back(place_instance(ShapeKind::Sphere, Mat4::translate({0, 0, -5}) * Mat4::scale({2, 1, 1}), 3));
  const dev::Hit hit = closest(scene, {{0, 0, 0}, {0, 0, -1}, 1e-4, 1e30});
  REQUIRE(hit.instance == 0);
  CHECK(hit.geometric_normal.w == Approx(4.0));
  check_near(xyz(hit.geometric_normal), {0, 0, 1});
  check_near(xyz(hit.shading_normal), {0, 0, 1});
  CHECK(hit.material == 3);
  CHECK(hit.primitive == 0);
  // Off-axis on the ellipsoid x^2/4 + z'^2 = 1 at x = 1: the normal is (x/4, 0, z'), normalised.
  const dev::Hit side = closest(scene, {{1, 0, 0}, {0, 0, -1}, 1e-4, 1e30});
  const double z = std::sqrt(0.75);
  CHECK(side.geometric_normal.w == Approx(5 - z));
  check_near(xyz(side.geometric_normal), normalize(Vec3{0.25, 0, z}));
}

TEST_CASE("a sphere under a similarity (tested in world space) reports t and the normal at its hit", "[bvh][device]") {
  Scene scene;
  // Radius 2 about (0, 0, -5), turned (which must change nothing), material 2.
  const Mat4 m = Mat4::translate({0, 0, -5}) * Mat4::rotate(40, normalize(Vec3{1, 2, 3})) * Mat4::scale({2, 2, 2});
  scene.instances.push_back(place_instance(ShapeKind::Sphere, m, 2));
  const dev::Hit front = closest(scene, {{0, 0, 0}, {0, 0, -1}, 1e-4, 1e30});
  REQUIRE(front.instance == 0);
  CHECK(front.geometric_normal.w == Approx(3.0));
  check_near(xyz(front.geometric_normal), {0, 0, 1});
  CHECK(front.material == 2);
  // At x = 1 the sphere's near side is at z = -5 + sqrt(3), where the normal is (1, 0, sqrt(3)) / 2.
  const dev::Hit side = closest(scene, {{1, 0, 0}, {0, 0, -1}, 1e-4, 1e30});
  CHECK(side.geometric_normal.w == Approx(5 - std::sqrt(3.0)));
  check_near(xyz(side.geometric_normal), {0.5, 0, std::sqrt(3.0) / 2});
  // From the centre, a ray (not unit) leaves through the far side.
  const dev::Hit inside = closest(scene, {{0, 0, -5}, {0, 4, 0}, 1e-4, 1e30});
  CHECK(inside.geometric_normal.w == Approx(0.5));
  check_near(xyz(inside.geometric_normal), {0, 1, 0});
  CHECK(closest(scene, {{0, 0, 0}, {0, 0, -1}, 1e-4, 2.9}).instance == CLRT_NO_HIT);
}

TEST_CASE("a miss reports no instance, and a ray from inside finds the way out", "[bvh][device]") {
  Scene scene;
  scene.instances.push_back(place_instance(ShapeKind::Cube, Mat4::identity()));
  CHECK(closest(scene, {{0, 5, 0}, {0, 1, 0}, 1e-4, 1e30}).instance == CLRT_NO_HIT);
  CHECK(closest(scene, {{0, 0, 0}, {0, 1, 0}, 1e-4, 0.5}).instance == CLRT_NO_HIT);
  const dev::Hit inside = closest(scene, {{0, 0, 0}, {0, 1, 0}, 1e-4, 1e30});
  REQUIRE(inside.instance == 0);
  CHECK(inside.geometric_normal.w == Approx(1.0));
  check_near(xyz(inside.geometric_normal), {0, 1, 0});
}

TEST_CASE("loose triangles take their own materials and keep their winding's normal", "[bvh][device]") {
  Scene scene;
  scene.triangles.push_back({{-1, -1, -2}, {1, -1, -2}, {0, 1, -2}, 2});   // counter-clockwise from +z
  scene.triangles.push_back({{-1, -1, -4}, {0, 1, -4}, {1, -1, -4}, 5});   // clockwise from +z
  const dev::Hit front = closest(scene, {{0, 0, 0}, {0, 0, -1}, 1e-4, 1e30});
  CHECK(front.material == 2);
  CHECK(front.geometric_normal.w == Approx(2.0));
  check_near(xyz(front.geometric_normal), {0, 0, 1});
  const dev::Hit back = closest(scene, {{0, 0, -3}, {0, 0, -1}, 1e-4, 1e30});
  CHECK(back.material == 5);
  check_near(xyz(back.geometric_normal), {0, 0, -1});
  const GeometryData g = build_geometry(scene);
  CHECK(g.triangle_source.at(g.meshes.at(0).first_triangle + back.primitive) == 1);
}

TEST_CASE("mesh shading normals interpolate the vertex normals under the instance's transform", "[bvh][device]") {
  Scene scene;
  scene.meshes.push_back(triangle_mesh_with_normals({0, 0, 1}, {1, 0, 1}, {0, 1, 1}));
  const Mat4 m = Mat4::translate({0, 0, -3}) * Mat4::scale({2, 1, 1});
  scene.instances.push_back(place_instance(ShapeKind::Mesh, m, 4));
  scene.instances.back().mesh = 0;
  // World point (0.5, 0.25, -3) is object point (0.25, 0.25, 0): weights 0.5, 0.25, 0.25.
  const dev::Hit hit = closest(scene, {{0.5, 0.25, 0}, {0, 0, -1}, 1e-4, 1e30});
  REQUIRE(hit.instance == 0);
  CHECK(hit.material == 4);
  CHECK(hit.primitive == 0);
  check_near(xyz(hit.geometric_normal), {0, 0, 1});
  const Vec3 object = normalize(Vec3{0, 0, 1}) * 0.5 + normalize(Vec3{1, 0, 1}) * 0.25 +
                      normalize(Vec3{0, 1, 1}) * 0.25;
  check_near(xyz(hit.shading_normal), normalize(scene.instances[0].transform.inverse().transposed().transform_vector(object)));
}

TEST_CASE("an instanced mesh is hit like its triangles written out as loose triangles", "[bvh][device]") {
  std::mt19937 rng(5);
  Scene instanced;
  instanced.meshes.push_back(ball_mesh(12, 16, false));
  Scene loose;
  for (int k = 0; k < 3; ++k) {
    const Mat4 m = random_transform(rng, 4);
    instanced.instances.push_back(place_instance(ShapeKind::Mesh, m, k));
    instanced.instances.back().mesh = 0;
    const MeshData& mesh = instanced.meshes[0];
    for (std::size_t c = 0; c < mesh.corners.size(); c += 3)
      loose.triangles.push_back({m.transform_point(mesh.positions[mesh.corners[c]]),
                                 m.transform_point(mesh.positions[mesh.corners[c + 1]]),
                                 m.transform_point(mesh.positions[mesh.corners[c + 2]]), k});
  }
  const std::vector<TestRay> rays = random_rays(rng, instanced, 2000);
  const GeometryData gi = build_geometry(instanced), gl = build_geometry(loose);
  const std::vector<dev::Hit> hi = device_closest_hits(gi, rays), hl = device_closest_hits(gl, rays);
  const int per_instance = static_cast<int>(instanced.meshes[0].corners.size() / 3);
  int compared = 0, hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (reference_closest_hit(instanced, rays[i].o, rays[i].d, rays[i].tmin, rays[i].tmax).ambiguous) continue;
    ++compared;
    REQUIRE((hi[i].instance == CLRT_NO_HIT) == (hl[i].instance == CLRT_NO_HIT));
    if (hi[i].instance == CLRT_NO_HIT) continue;
    ++hits;
    const ObjectId a = hit_object(gi, hi[i]), b = hit_object(gl, hl[i]);
    CHECK(a.instance * per_instance + a.triangle == b.triangle);
    CHECK(hi[i].material == hl[i].material);
    CHECK(hi[i].geometric_normal.w == Approx(hl[i].geometric_normal.w).epsilon(1e-4));
    check_near(xyz(hi[i].geometric_normal), xyz(hl[i].geometric_normal));
  }
  CHECK(compared > 1900);
  CHECK(hits > 300);
}
