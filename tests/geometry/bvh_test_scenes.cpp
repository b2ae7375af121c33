#include "bvh_test_scenes.hpp"

#include <cmath>

#include "uv_sphere.hpp"

namespace clrt::bvhtest {
namespace {

double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Vec3 random_point(std::mt19937& rng, double spread) {
  return {uniform(rng, -spread, spread), uniform(rng, -spread, spread), uniform(rng, -spread, spread)};
}

Vec3 random_direction(std::mt19937& rng) {
  for (;;) {
    const Vec3 v = random_point(rng, 1);
    const double len = length(v);
    if (len > 0.1 && len <= 1) return v / len;
  }
}

Vec3 instance_centre(const Scene& scene, std::size_t i) {
  return scene.instances[i].transform.transform_point({0, 0, 0});
}

}  // namespace

Mat4 random_transform(std::mt19937& rng, double spread) {
  const Vec3 scale{uniform(rng, 0.3, 2), uniform(rng, 0.3, 2), uniform(rng, 0.3, 2)};
  return Mat4::translate(random_point(rng, spread)) *
         Mat4::rotate(uniform(rng, 0, 360), random_direction(rng)) * Mat4::scale(scale);
}

Mat4 random_similarity(std::mt19937& rng, double spread, double min_scale, double max_scale) {
  const double scale = uniform(rng, min_scale, max_scale);
  return Mat4::translate(random_point(rng, spread)) *
         Mat4::rotate(uniform(rng, 0, 360), random_direction(rng)) * Mat4::scale({scale, scale, scale});
}

MeshData triangle_mesh_with_normals(const Vec3& n0, const Vec3& n1, const Vec3& n2) {
  MeshData mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.normals = {n0, n1, n2};
  mesh.corners = {0, 1, 2};
  mesh.corner_normals = {0, 1, 2};
  return mesh;
}

MeshData ball_mesh(int rings, int segments, bool with_normals) {
  scenes::TriangleMesh ball = scenes::uv_sphere(rings, segments);
  MeshData mesh;
  mesh.path = "ball";
  mesh.positions = std::move(ball.positions);
  mesh.corners = std::move(ball.corners);
  if (with_normals) {
    mesh.normals = mesh.positions;
    mesh.corner_normals = mesh.corners;
  }
  return mesh;
}

Scene random_scene(std::mt19937& rng, int count, int triangles) {
  Scene scene;
  scene.materials.resize(4);
  const double spread = 2.0 * std::cbrt(static_cast<double>(count));
  const ShapeKind kinds[] = {ShapeKind::Sphere, ShapeKind::Cube, ShapeKind::Cylinder, ShapeKind::Cone};
  for (int i = 0; i < count; ++i) {
    InstanceSpec s = place_instance(kinds[i % 4], random_transform(rng, spread), i % 4);
    s.cone_r0 = uniform(rng, 0, 1.5);
    s.cone_r1 = i % 8 == 3 ? 0.0 : uniform(rng, 0.2, 1.5);
    scene.instances.push_back(s);
  }
  scene.instances.push_back(place_instance(ShapeKind::Plane, Mat4::translate({0, -spread - 3, 0}), 1));
  scene.meshes.push_back(ball_mesh(6, 8, true));
  for (int k = 0; k < 2; ++k) {
    InstanceSpec s = place_instance(ShapeKind::Mesh, random_transform(rng, spread), 2);
    s.mesh = 0;
    scene.instances.push_back(s);
  }
  for (int t = 0; t < triangles; ++t) {
    const Vec3 c = random_point(rng, spread);
    scene.triangles.push_back({c + random_point(rng, 1.5), c + random_point(rng, 1.5),
                               c + random_point(rng, 1.5), t % 4});
  }
  return scene;
}

Scene sphere_scene(std::mt19937& rng, int count) {
  Scene scene;
  scene.materials.resize(3);
  const double spread = std::cbrt(static_cast<double>(count));
  for (int i = 0; i < count; ++i) {
    const double size = std::pow(10.0, uniform(rng, -2, 0.5));
    scene.instances.push_back(place_instance(ShapeKind::Sphere, random_similarity(rng, spread, size, size), i % 3));
  }
  for (int i = 0; i < 5; ++i) scene.instances.push_back(place_instance(ShapeKind::Sphere, random_transform(rng, spread)));
  scene.meshes.push_back(ball_mesh(6, 8, false));
  InstanceSpec ball = place_instance(ShapeKind::Mesh, random_transform(rng, spread), 1);
  ball.mesh = 0;
  scene.instances.push_back(ball);
  return scene;
}

std::vector<TestRay> random_rays(std::mt19937& rng, const Scene& scene, int count) {
  const double spread = 2.5 * std::cbrt(static_cast<double>(scene.instances.size()));
  std::vector<TestRay> rays;
  for (int i = 0; i < count; ++i) {
    TestRay ray;
    ray.o = random_point(rng, spread);
    ray.d = random_direction(rng);
    const std::size_t target = rng() % scene.instances.size();
    switch (i % 6) {
      case 1: ray.d = i % 12 < 6 ? Vec3{1, 0, 0} : Vec3{0, 0, -1}; break;
      case 2: ray.d = Vec3{0, (i % 4 < 2) ? 1.0 : -1.0, 0}; break;
      case 3: ray.d = normalize(instance_centre(scene, target) + random_point(rng, 0.3) - ray.o); break;
      case 4: ray.o = instance_centre(scene, target); break;
      case 5: ray.d = ray.d * uniform(rng, 0.25, 4); ray.tmax = uniform(rng, 0.5, spread); break;
      default: break;
    }
    rays.push_back(ray);
  }
  return rays;
}

}  // namespace clrt::bvhtest
