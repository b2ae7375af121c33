// The emitter table (src/geometry/emitter_table.cpp) on the host: which glowing surfaces become
// rows, that every triangle row's corners turn its normal to the side the device's (M^-1)^T
// calls the front (mirroring transforms included), the rows' areas, and the cumulative shares
// of the power by which the glow light picks them.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "geometry/geometry_data.hpp"
#include "scene/scene.hpp"

using namespace clrt;

namespace {

Vec3 xyz(const dev::f4& v) { return {v.x, v.y, v.z}; }

int glowing(Scene& scene, Vec3 emission) {
  MaterialSpec m;
  m.emission = emission;
  scene.materials.push_back(m);
  return static_cast<int>(scene.materials.size() - 1);
}

// The glow mark and the rows of a scene of one instance.
struct Rows {
  dev::u32 glow = CLRT_NO_GLOW;
  std::vector<dev::Emitter> rows;
};

Rows rows_of(const Scene& scene) {
  const GeometryData g = build_geometry(scene);
  REQUIRE(g.instances.size() == 1);
  return {g.instances[0].glow, g.emitters};
}

double area(const dev::Emitter& e) { return length(cross(xyz(e.edge1), xyz(e.edge2))) / 2; }

}  // namespace

TEST_CASE("a glowing cube is twelve triangles facing out, mirrored or not", "[geometry][glow]") {
  for (const bool mirrored : {false, true}) {
    INFO((mirrored ? "mirrored" : "not mirrored"));
    Scene scene;
    scene.materials.resize(1);
    const Vec3 centre{1, -2, 0.5};
    const Mat4 m = Mat4::translate(centre) * Mat4::rotate(25, {1, 1, 0}) *
                   Mat4::scale({mirrored ? -1.0 : 1.0, 2, 3});
    scene.instances.push_back(place_instance(ShapeKind::Cube, m, glowing(scene, {1, 1, 1})));
    const Rows r = rows_of(scene);
    CHECK(r.glow == CLRT_GLOW_TRIANGLES);
    REQUIRE(r.rows.size() == 12);
    double total = 0;
    for (const dev::Emitter& e : r.rows) {
      total += area(e);
      const Vec3 centroid = xyz(e.origin) + (xyz(e.edge1) + xyz(e.edge2)) / 3;
      CHECK(dot(cross(xyz(e.edge1), xyz(e.edge2)), centroid - centre) > 0);
      CHECK(e.edge1.w == 0);
    }
    CHECK(total == Approx(2 * (2 * 4 + 2 * 6 + 4 * 6)).epsilon(1e-6));
  }
}

TEST_CASE("a glowing mesh's rows face where (M^-1)^T turns its normals", "[geometry][glow]") {
  for (const bool mirrored : {false, true}) {
    INFO((mirrored ? "mirrored" : "not mirrored"));
    Scene scene;
    scene.materials.resize(1);
    MeshData triangle;
    triangle.path = "tri.obj";
    triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    triangle.corners = {0, 1, 2};
    scene.meshes.push_back(triangle);
    const Mat4 m = Mat4::translate({0, 0, -3}) * Mat4::scale({mirrored ? -2.0 : 2.0, 1, 1});
    InstanceSpec mesh = place_instance(ShapeKind::Mesh, m, glowing(scene, {0, 2, 0}));
    mesh.mesh = 0;
    scene.instances.push_back(mesh);
    const Rows r = rows_of(scene);
    CHECK(r.glow == CLRT_GLOW_TRIANGLES);
    REQUIRE(r.rows.size() == 1);
    // The object normal +z, carried by (M^-1)^T, stays +z: the scale along x does not turn it.
    CHECK(cross(xyz(r.rows[0].edge1), xyz(r.rows[0].edge2)).z > 0);
    CHECK(area(r.rows[0]) == Approx(1.0));
    CHECK(xyz(r.rows[0].radiance) == Vec3{0, 2, 0});
  }
}

TEST_CASE("a mesh's faces glow by their own MTL materials where the instance keeps them",
          "[geometry][glow][mtl]") {
  for (const bool keep : {true, false}) {
    INFO((keep ? "mtl on" : "mtl off"));
    Scene scene;
    scene.materials.resize(1);
    const int glow = glowing(scene, {0, 3, 0});
    // Two triangles: the first under a usemtl naming the glowing material, the second before any.
    MeshData quad;
    quad.path = "quad.obj";
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.corners = {0, 1, 2, 0, 2, 3};
    quad.material_names = {{"lamp", {}}};
    quad.triangle_names = {0, kNoMeshMaterial};
    quad.name_materials = {glow};
    scene.meshes.push_back(quad);
    InstanceSpec mesh = place_instance(ShapeKind::Mesh, Mat4::identity(), 0);
    mesh.mesh = 0;
    mesh.mesh_materials = keep;
    scene.instances.push_back(mesh);
    const Rows r = rows_of(scene);
    if (!keep) {
      CHECK(r.rows.empty());
      CHECK(r.glow == CLRT_NO_GLOW);
      continue;
    }
    CHECK(r.glow == CLRT_GLOW_TRIANGLES);
    REQUIRE(r.rows.size() == 1);
    CHECK(xyz(r.rows[0].origin) == Vec3{0, 0, 0});
    CHECK(xyz(r.rows[0].radiance) == Vec3{0, 3, 0});
  }
}

TEST_CASE("a glowing sphere is one row, and planes, cylinders, cones and ellipsoids none",
          "[geometry][glow]") {
  Scene scene;
  scene.materials.resize(1);
  const int glow = glowing(scene, {1, 2, 3});
  scene.instances.push_back(place_instance(
      ShapeKind::Sphere, Mat4::translate({1, 2, 3}) * Mat4::rotate(40, {0, 1, 1}) * Mat4::scale({0.5, 0.5, 0.5}), glow));
  scene.instances.push_back(place_instance(ShapeKind::Sphere, Mat4::scale({1, 2, 1}), glow));
  scene.instances.push_back(place_instance(ShapeKind::Plane, Mat4::identity(), glow));
  scene.instances.push_back(place_instance(ShapeKind::Cylinder, Mat4::identity(), glow));
  scene.instances.push_back(place_instance(ShapeKind::Cone, Mat4::identity(), glow));
  scene.instances.push_back(place_instance(ShapeKind::Sphere, Mat4::translate({5, 0, 0}), 0));
  const GeometryData g = build_geometry(scene);
  REQUIRE(g.emitters.size() == 1);
  const dev::Emitter& e = g.emitters[0];
  CHECK(xyz(e.origin).x == Approx(1));
  CHECK(xyz(e.origin).y == Approx(2));
  CHECK(xyz(e.origin).z == Approx(3));
  CHECK(e.edge1.w == Approx(0.5));
  CHECK(e.origin.w == 1.0f);
  for (std::size_t i = 0; i < g.instances.size(); ++i)
    CHECK(g.instances[i].glow == (g.instance_source[i] == 0 ? 0u : CLRT_NO_GLOW));
  const double luminance = 0.2126 * 1 + 0.7152 * 2 + 0.0722 * 3;
  CHECK(g.emitter_power == Approx(luminance * 4 * M_PI * 0.25));
}

TEST_CASE("rows share the samples by luminance times area, cumulatively", "[geometry][glow]") {
  Scene scene;
  scene.materials.resize(1);
  const int dim = glowing(scene, {1, 1, 1}), bright = glowing(scene, {3, 3, 3});
  scene.triangles.push_back({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, dim});        // area 0.5
  scene.triangles.push_back({{0, 0, 1}, {2, 0, 1}, {0, 2, 1}, bright});     // area 2
  scene.triangles.push_back({{0, 0, 2}, {1, 0, 2}, {0, 1, 2}, 0});          // no glow
  scene.triangles.push_back({{0, 0, 3}, {1, 0, 3}, {2, 0, 3}, bright});     // no area
  const GeometryData g = build_geometry(scene);
  REQUIRE(g.emitters.size() == 2);
  CHECK(g.emitter_power == Approx(0.5 + 6));
  CHECK(g.emitters[0].origin.w == Approx(0.5 / 6.5));
  CHECK(g.emitters[1].origin.w == 1.0f);
  CHECK(g.instances.back().glow == CLRT_GLOW_TRIANGLES);
}
