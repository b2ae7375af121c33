#include "bench_scenes.hpp"

#include <cmath>
#include <random>

#include "uv_sphere.hpp"

namespace clrt::bench {
namespace {

// A displaced UV sphere of about `triangles` triangles.
MeshData lumpy_ball(int triangles) {
  const int segments = std::max(4, static_cast<int>(std::sqrt(triangles)));
  const int rings = std::max(2, triangles / (2 * segments));
  scenes::TriangleMesh ball = scenes::uv_sphere(rings, segments, [](double theta, double phi) {
    return 1 + 0.1 * std::sin(7 * theta) * std::cos(5 * phi);
  });
  MeshData mesh;
  mesh.path = "lumpy-ball";
  mesh.positions = std::move(ball.positions);
  mesh.corners = std::move(ball.corners);
  return mesh;
}

Mat4 random_placement(std::mt19937& rng, double spread) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 axis = normalize(Vec3{u(rng), u(rng), u(rng)} + Vec3{0, 0, 1e-3});
  const Vec3 scale{0.5 + 0.4 * u(rng), 0.5 + 0.4 * u(rng), 0.5 + 0.4 * u(rng)};
  return Mat4::translate(Vec3{u(rng), u(rng), u(rng)} * spread) * Mat4::rotate(180 * u(rng), axis) *
         Mat4::scale(scale);
}

double spread_for(int count) { return 2.0 * std::cbrt(static_cast<double>(count)); }

}  // namespace

Scene mesh_scene(int triangles) {
  Scene scene;
  scene.materials.resize(1);
  scene.meshes.push_back(lumpy_ball(triangles));
  scene.instances.push_back(place_instance(ShapeKind::Mesh, Mat4::identity()));
  scene.instances.back().mesh = 0;
  return scene;
}

Scene shapes_scene(int count) {
  Scene scene;
  scene.materials.resize(1);
  std::mt19937 rng(1);
  const ShapeKind kinds[] = {ShapeKind::Sphere, ShapeKind::Cylinder, ShapeKind::Cone, ShapeKind::Cube};
  for (int i = 0; i < count; ++i)
    scene.instances.push_back(place_instance(kinds[i % 4], random_placement(rng, spread_for(count))));
  scene.instances.push_back(place_instance(ShapeKind::Plane, Mat4::translate({0, -spread_for(count) - 2, 0})));
  return scene;
}

Scene mesh_instances_scene(int count) {
  Scene scene;
  scene.materials.resize(1);
  scene.meshes.push_back(lumpy_ball(1000));
  std::mt19937 rng(2);
  for (int i = 0; i < count; ++i) {
    scene.instances.push_back(place_instance(ShapeKind::Mesh, random_placement(rng, spread_for(count))));
    scene.instances.back().mesh = 0;
  }
  return scene;
}

}  // namespace clrt::bench
