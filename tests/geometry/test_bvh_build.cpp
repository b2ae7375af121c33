// The host side of the acceleration structure: the geometry tables and the BVH's invariants.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <set>

#include "bvh_test_scenes.hpp"
#include "bvh_tree_check.hpp"
#include "geometry/bvh_builder.hpp"
#include "geometry/bvh_layout.hpp"
#include "geometry/bvh_partition.hpp"
#include "geometry/bvh_split.hpp"
#include "geometry/instance_bounds.hpp"
#include "geometry/geometry_data.hpp"
#include "geometry/mesh_table.hpp"
#include "math/parallel_for.hpp"
#include "shared/ray.h"

using namespace clrt;
using namespace clrt::bvhtest;

namespace {

Vec3 to_vec(const dev::f4& v) { return {v.x, v.y, v.z}; }

std::vector<Vec3> points_of(const dev::Triangle& t) { return {to_vec(t.v0), to_vec(t.v1), to_vec(t.v2)}; }

// The vertices of the rows of the per-triangle tables, read from the scene through
// triangle_source.
class SceneTriangles {
 public:
  SceneTriangles(const Scene& scene, const GeometryData& g) : g_(g) {
    for (const MeshData& mesh : scene.meshes) sources_.emplace_back(mesh);
    sources_.emplace_back(scene.triangles);
  }

  std::vector<Vec3> points(std::uint32_t t) const {
    std::size_t m = 0;
    while (t >= g_.meshes[m].first_triangle + g_.meshes[m].triangle_count) ++m;
    return points_of(sources_[m].triangle(g_.triangle_source[t]));
  }

 private:
  const GeometryData& g_;
  std::vector<TriangleSource> sources_;
};

// Points spread over the surface of a canonical shape, in object space: all of them for a
// cube's corners and for the rims of a cylinder or cone (which hold their extreme points).
std::vector<Vec3> shape_points(const InstanceSpec& s, int count) {
  std::vector<Vec3> points;
  const double r0 = s.shape == ShapeKind::Cone ? s.cone_r0 : 1;
  const double r1 = s.shape == ShapeKind::Cone ? s.cone_r1 : 1;
  for (int k = 0; k < count; ++k) {
    const double phi = 2 * M_PI * k / count, c = std::cos(phi), sn = std::sin(phi);
    if (s.shape == ShapeKind::Sphere) {
      // Fibonacci sphere: evenly spread, so extreme points in any direction are near one.
      const double y = 1 - 2 * (k + 0.5) / count, r = std::sqrt(1 - y * y);
      const double a = k * M_PI * (3 - std::sqrt(5.0));
      points.push_back({r * std::cos(a), y, r * std::sin(a)});
    } else if (s.shape == ShapeKind::Cube) {
      points.push_back({k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0});
    } else {
      points.push_back({r0 * c, -1, r0 * sn});
      points.push_back({r1 * c, 1, r1 * sn});
    }
  }
  return points;
}

// Points on the surface of an instance (a mesh's vertices), in world space.
std::vector<Vec3> instance_points(const Scene& scene, const GeometryData& g, const SceneTriangles& triangles,
                                  std::uint32_t i) {
  const int source = g.instance_source[i];
  std::vector<Vec3> points;
  if (g.instances[i].shape == CLRT_SHAPE_MESH) {
    const dev::Mesh& mesh = g.meshes[g.instances[i].mesh];
    for (std::uint32_t t = mesh.first_triangle; t < mesh.first_triangle + mesh.triangle_count; ++t)
      for (const Vec3& p : triangles.points(t)) points.push_back(p);
  } else {
    points = shape_points(scene.instances[source], 256);
  }
  if (source >= 0)
    for (Vec3& p : points) p = scene.instances[source].transform.transform_point(p);
  return points;
}

bool identity_rows(const dev::Instance& inst) {
  for (int r = 0; r < 3; ++r) {
    const dev::f4& row = inst.world_to_object[r];
    const float want[4] = {r == 0 ? 1.0f : 0.0f, r == 1 ? 1.0f : 0.0f, r == 2 ? 1.0f : 0.0f, 0.0f};
    if (row.x != want[0] || row.y != want[1] || row.z != want[2] || row.w != want[3]) return false;
  }
  return true;
}

// The meshes the top level leads straight into: each one's packets name the instance, the
// only one to place that mesh, with the identity transform.
std::set<std::uint32_t> merged_mesh_roots(const GeometryData& g, std::vector<std::string>& errors) {
  std::set<std::uint32_t> roots;
  for (std::size_t m = 0; m < g.meshes.size(); ++m) {
    const std::uint32_t instance = packets_instance(g.nodes, g.meshes[m].root_node, errors);
    if (instance == CLRT_NO_HIT) continue;
    roots.insert(g.meshes[m].root_node);
    int users = 0;
    for (const dev::Instance& inst : g.instances) users += inst.shape == CLRT_SHAPE_MESH && inst.mesh == m;
    const dev::Instance& inst = g.instances.at(instance);
    if (inst.shape != CLRT_SHAPE_MESH || inst.mesh != m || users != 1 || !identity_rows(inst))
      errors.push_back("mesh " + std::to_string(m) + " is merged into the top level for instance " +
                       std::to_string(instance) + ", which is not its only identity instance");
  }
  return roots;
}

TreeShape check_scene_bvh(const Scene& scene, const GeometryData& g) {
  std::vector<std::string> errors;
  const auto instance_count = static_cast<std::uint32_t>(g.instances.size());
  const std::set<std::uint32_t> merged = merged_mesh_roots(g, errors);
  const SceneTriangles triangles(scene, g);
  const TreeShape top = check_tree(g.nodes, 0, Level::Top, g.plane_count, instance_count - g.plane_count,
                                   [&](std::uint32_t i) { return instance_points(scene, g, triangles, i); }, errors,
                                   merged);
  CHECK(top.max_leaf <= CLRT_BVH_MAX_SPHERES);
  // A mesh instance's packet holds its transform and leads to its mesh's root.
  for (const dev::BvhMeshInstancePacket& p : top.mesh_instances) {
    const dev::Instance& inst = g.instances.at(p.instance);
    REQUIRE(inst.shape == CLRT_SHAPE_MESH);
    CHECK(p.root == g.meshes.at(inst.mesh).root_node);
    for (int r = 0; r < 3; ++r) {
      CHECK(p.world_to_object[r].x == inst.world_to_object[r].x);
      CHECK(p.world_to_object[r].y == inst.world_to_object[r].y);
      CHECK(p.world_to_object[r].z == inst.world_to_object[r].z);
      CHECK(p.world_to_object[r].w == inst.world_to_object[r].w);
    }
  }
  CHECK(top.depth <= CLRT_BVH_MAX_DEPTH);
  for (const dev::Mesh& mesh : g.meshes) {
    const TreeShape bottom = check_tree(g.nodes, mesh.root_node, Level::Mesh, mesh.first_triangle,
                                        mesh.triangle_count, [&](std::uint32_t t) { return triangles.points(t); },
                                        errors);
    CHECK(bottom.max_leaf <= CLRT_BVH_MAX_TRIANGLES);
    CHECK(bottom.depth <= CLRT_BVH_MAX_DEPTH);
  }
  INFO((errors.empty() ? std::string() : errors.front()));
  CHECK(errors.empty());
  return top;
}

}  // namespace

TEST_CASE("geometry tables: planes first, one mesh per model, loose triangles last", "[bvh]") {
  std::mt19937 rng(7);
  const Scene scene = random_scene(rng, 40, 30);
  const GeometryData g = build_geometry(scene);
  REQUIRE(g.instances.size() == scene.instances.size() + 1);
  REQUIRE(g.plane_count == 1);
  CHECK(g.instances[0].shape == CLRT_SHAPE_PLANE);
  for (std::size_t i = 1; i < g.instances.size(); ++i) CHECK(g.instances[i].shape != CLRT_SHAPE_PLANE);
  REQUIRE(g.meshes.size() == 2);
  // Only the model, which has vertex normals, has rows of them.
  CHECK(g.meshes[0].normals == 0);
  CHECK(g.meshes[1].normals == CLRT_NO_NORMALS);
  CHECK(g.meshes[1].triangle_count == 30);
  CHECK(g.triangle_count() == scene.meshes[0].corners.size() / 3 + 30);
  CHECK(g.triangle_normals.size() == g.meshes[0].triangle_count);
  CHECK(g.triangle_materials.size() == 30);  // the loose triangles' only
  int loose_instances = 0;
  for (std::size_t i = 0; i < g.instances.size(); ++i) {
    if (g.instance_source[i] >= 0) {
      CHECK(g.instances[i].material == static_cast<dev::u32>(scene.instances[g.instance_source[i]].material));
      CHECK(g.instances[i].material_rows == CLRT_NO_MATERIAL_ROWS);  // the mesh names no usemtl
      continue;
    }
    ++loose_instances;
    CHECK(g.instances[i].material_rows == 0);
    CHECK(g.instances[i].mesh == 1);
    CHECK(g.instances[i].world_to_object[0].x == 1.0f);
    CHECK(g.instances[i].world_to_object[0].w == 0.0f);
  }
  CHECK(loose_instances == 1);
  // Each loose triangle's row holds the material of the scene's triangle its source index names,
  // each of them once.
  const dev::Mesh& loose = g.meshes[1];
  std::set<dev::u32> sources;
  for (std::uint32_t t = loose.first_triangle; t < loose.first_triangle + loose.triangle_count; ++t) {
    const TriangleSpec& spec = scene.triangles.at(g.triangle_source[t]);
    CHECK(g.triangle_materials[t - loose.first_triangle] == static_cast<dev::u32>(spec.material));
    sources.insert(g.triangle_source[t]);
  }
  CHECK(sources.size() == scene.triangles.size());
  // Per triangle with vertex normals the device holds them (36 bytes), and per loose triangle
  // its material (4); no triangle table: the BVH's leaf packets carry the vertices. No triangle
  // has (u, v) of its own.
  CHECK(g.triangle_texcoords.empty());
  CHECK(g.device_bytes() == g.instances.size() * 80 + g.meshes.size() * 32 + g.meshes[0].triangle_count * 36 +
                                30 * 4 + g.nodes.size() * sizeof(dev::BvhNode));
}

TEST_CASE("mesh vertex normals are stored unit length, in the triangle's corner order", "[bvh]") {
  Scene scene;
  scene.meshes.push_back(triangle_mesh_with_normals({0, 0, 2}, {0, 3, 4}, {0, 0, 0}));
  scene.instances.push_back(place_instance(ShapeKind::Mesh, Mat4::identity()));
  scene.instances.back().mesh = 0;
  const GeometryData g = build_geometry(scene);
  const dev::TriangleNormals& n = g.triangle_normals.at(0);
  CHECK(n.n[2] == Approx(1.0));
  CHECK(n.n[4] == Approx(0.6));
  CHECK(n.n[5] == Approx(0.8));
  // A zero normal falls back to the face normal (+z for this counter-clockwise triangle).
  CHECK(n.n[8] == Approx(1.0));
}

TEST_CASE("BVH invariants hold on random scenes", "[bvh]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    std::mt19937 rng(seed);
    const Scene scene = random_scene(rng, 300 * seed, 500);
    check_scene_bvh(scene, build_geometry(scene));
  }
}

TEST_CASE("spheres under similarities share leaves, other instances are leaves of their own", "[bvh]") {
  for (unsigned seed : {4u, 5u}) {
    std::mt19937 rng(seed);
    const Scene scene = sphere_scene(rng, 500);
    const TreeShape top = check_scene_bvh(scene, build_geometry(scene));
    CHECK(top.max_leaf > 1);
    CHECK(top.leaves * 2 < static_cast<int>(scene.instances.size()));
  }
}

TEST_CASE("meshes placed once with the identity transform are part of the top level", "[bvh]") {
  Scene scene;
  for (int m = 0; m < 3; ++m) scene.meshes.push_back(ball_mesh(4, 6, false));
  const auto add = [&](int mesh, const Mat4& transform) {
    scene.instances.push_back(place_instance(ShapeKind::Mesh, transform));
    scene.instances.back().mesh = mesh;
  };
  add(0, Mat4::identity());                  // merged
  add(1, Mat4::identity());                  // placed twice: not merged
  add(1, Mat4::translate({3, 0, 0}));
  add(2, Mat4::translate({0, 3, 0}));        // not the identity: not merged
  scene.triangles.push_back({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}, 0});  // the loose mesh: merged
  const GeometryData g = build_geometry(scene);
  std::vector<std::string> errors;
  const std::set<std::uint32_t> merged = merged_mesh_roots(g, errors);
  CHECK(merged == std::set<std::uint32_t>{g.meshes[0].root_node, g.meshes[3].root_node});
  check_scene_bvh(scene, g);
}

TEST_CASE("a scene of one mesh placed as it is has that mesh's level as its top level", "[bvh]") {
  std::mt19937 rng(8);
  Scene scene;
  for (int t = 0; t < 300; ++t) {
    std::uniform_real_distribution<double> u(-5, 5);
    const Vec3 c{u(rng), 0, u(rng)};
    scene.triangles.push_back({c, c + Vec3{1, 0, 0}, c + Vec3{0, 1, 0.5}, t % 3});
  }
  scene.instances.push_back(place_instance(ShapeKind::Plane, Mat4::translate({0, -1, 0})));  // planes stay outside
  const GeometryData g = build_geometry(scene);
  REQUIRE(g.meshes.size() == 1);
  CHECK(g.meshes[0].root_node == 0);
  check_scene_bvh(scene, g);
}

TEST_CASE("transformed boxes hold the eight corners of every box carried by the transform", "[bvh]") {
  std::mt19937 rng(14);
  const auto u = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  for (int trial = 0; trial < 200; ++trial) {
    const Mat4 m = random_transform(rng, 50);
    Box boxes[3];
    Vec3 lo{1e300, 1e300, 1e300}, hi = -lo;
    for (Box& b : boxes) {
      const Vec3 c{u(-5, 5), u(-5, 5), u(-5, 5)};
      b.grow(float(c.x - u(0, 2)), float(c.y - u(0, 2)), float(c.z));
      b.grow(float(c.x + u(0, 2)), float(c.y), float(c.z + u(0, 2)));
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p = m.transform_point({corner & 1 ? b.hi[0] : b.lo[0], corner & 2 ? b.hi[1] : b.lo[1],
                                          corner & 4 ? b.hi[2] : b.lo[2]});
        lo = min(lo, p);
        hi = max(hi, p);
      }
    }
    const Box got = transformed_box(BoxSet({boxes[0], boxes[1], boxes[2], Box{}}), m);
    INFO("trial " << trial);
    for (int a = 0; a < 3; ++a) {
      // Contains the corners, and pads them by no more than a thousandth of the size.
      const double slack = 1e-3 * length(hi - lo);
      CHECK(got.lo[a] <= lo[a]);
      CHECK(got.hi[a] >= hi[a]);
      CHECK(got.lo[a] >= lo[a] - slack);
      CHECK(got.hi[a] <= hi[a] + slack);
    }
  }
  CHECK(transformed_box(BoxSet({}), Mat4::identity()).empty());
}

TEST_CASE("world spheres: the centre and radius of spheres under similarities only", "[bvh]") {
  const Mat4 similarity = Mat4::translate({1, -2, 3}) * Mat4::rotate(33, normalize(Vec3{1, 1, 0})) *
                          Mat4::scale({0.5, 0.5, 0.5});
  const std::optional<WorldSphere> s = world_sphere(place_instance(ShapeKind::Sphere, similarity));
  REQUIRE(s);
  CHECK(s->center.x == Approx(1));
  CHECK(s->center.y == Approx(-2));
  CHECK(s->center.z == Approx(3));
  CHECK(s->radius == Approx(0.5));
  // Mirrored is still a similarity.
  CHECK(world_sphere(place_instance(ShapeKind::Sphere, Mat4::scale({-2, 2, 2}))));
  CHECK_FALSE(world_sphere(place_instance(ShapeKind::Sphere, Mat4::scale({2, 2, 2.001}))));
  CHECK_FALSE(world_sphere(place_instance(ShapeKind::Sphere, Mat4::rotate(20, {0, 0, 1}) * Mat4::scale({1, 2, 1}))));
  CHECK_FALSE(world_sphere(place_instance(ShapeKind::Cube, similarity)));
}

TEST_CASE("a scene of planes only has an empty top level", "[bvh]") {
  Scene scene;
  scene.instances.push_back(place_instance(ShapeKind::Plane, Mat4::identity()));
  const GeometryData g = build_geometry(scene);
  REQUIRE(g.nodes.size() == 1);
  for (int k = 0; k < CLRT_BVH_WIDTH; ++k) CHECK(g.nodes[0].count[k] == 0);
  check_scene_bvh(scene, g);
}

TEST_CASE("coincident triangles are split by count, within the depth limit", "[bvh]") {
  Scene scene;
  for (int t = 0; t < 5000; ++t) scene.triangles.push_back({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0});
  check_scene_bvh(scene, build_geometry(scene));
}

TEST_CASE("nested boxes that the SAH peels one by one stay within the depth limit", "[bvh]") {
  std::vector<Box> boxes(3000);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const float size = std::pow(1.01f, static_cast<float>(i));
    boxes[i].grow(0, 0, 0);
    boxes[i].grow(size, size, size);
  }
  for (unsigned leaf_size : {1u, 4u, 8u}) {
    BvhBuildSettings settings;
    settings.max_leaf_size = leaf_size;
    const BvhTree tree = build_bvh(boxes, settings);
    // Laid out as a mesh of degenerate triangles from each box's low to its high corner, whose
    // boxes are the boxes.
    std::vector<TriangleSpec> triangles;
    for (const Box& b : boxes) {
      const Vec3 lo{b.lo[0], b.lo[1], b.lo[2]}, hi{b.hi[0], b.hi[1], b.hi[2]};
      triangles.push_back({lo, hi, lo, 0});
    }
    const TriangleSource source(triangles);
    BvhTable table;
    const std::uint32_t root = append_mesh_level(tree, source, 0, CLRT_NO_HIT, table);
    std::vector<std::string> errors;
    const TreeShape shape = check_tree(table, root, Level::Mesh, 0, static_cast<std::uint32_t>(boxes.size()),
                                       [&](std::uint32_t i) { return points_of(source.triangle(tree.order[i])); },
                                       errors);
    INFO("leaf size " << leaf_size << ": " << (errors.empty() ? std::string() : errors.front()));
    CHECK(errors.empty());
    CHECK(shape.depth <= CLRT_BVH_MAX_DEPTH);
    CHECK(static_cast<unsigned>(shape.max_leaf) <= leaf_size);
    CHECK(tree.depth == shape.depth);
  }
}

TEST_CASE("shape boxes hug the transformed shapes", "[bvh]") {
  std::mt19937 rng(9);
  const ShapeKind kinds[] = {ShapeKind::Sphere, ShapeKind::Cube, ShapeKind::Cylinder, ShapeKind::Cone};
  for (int i = 0; i < 40; ++i) {
    InstanceSpec s = place_instance(kinds[i % 4], random_transform(rng, 10));
    s.cone_r0 = i % 8 == 3 ? 0.0 : 0.7;
    s.cone_r1 = 1.3;
    Vec3 lo{1e30, 1e30, 1e30}, hi = -lo;
    for (const Vec3& p : shape_points(s, 20000)) {
      lo = min(lo, s.transform.transform_point(p));
      hi = max(hi, s.transform.transform_point(p));
    }
    const Box box = shape_world_box(s);
    INFO("shape " << i);
    for (int a = 0; a < 3; ++a) {
      // Contains every point, and no more than a thousandth of the size beyond them.
      const double slack = 1e-3 * (hi[a] - lo[a]);
      CHECK(box.lo[a] <= lo[a]);
      CHECK(box.hi[a] >= hi[a]);
      CHECK(box.lo[a] >= lo[a] - slack);
      CHECK(box.hi[a] <= hi[a] + slack);
    }
  }
}

TEST_CASE("the BVH and its tables are the same on any number of threads", "[bvh]") {
  // Large enough for every parallel path: ranges binned and partitioned in blocks, subtrees
  // built side by side, meshes built side by side, a mesh file parsed in slices.
  std::mt19937 rng(21);
  Scene scene = random_scene(rng, 3000, 2000);
  scene.meshes.push_back(ball_mesh(180, 200, true));  // 72,000 triangles
  scene.instances.push_back(place_instance(ShapeKind::Mesh, Mat4::identity()));
  scene.instances.back().mesh = static_cast<int>(scene.meshes.size()) - 1;
  const auto build_on = [&](unsigned threads) {
    parallel_thread_limit = threads;
    GeometryData g = build_geometry(scene);
    parallel_thread_limit = 0;
    return g;
  };
  const GeometryData one = build_on(1);
  for (unsigned threads : {2u, 7u}) {
    INFO(threads << " threads");
    const GeometryData many = build_on(threads);
    REQUIRE(many.nodes.size() == one.nodes.size());
    CHECK(std::memcmp(many.nodes.data(), one.nodes.data(), one.nodes.size() * sizeof(dev::BvhNode)) == 0);
    CHECK(many.triangle_source == one.triangle_source);
    CHECK(many.instance_source == one.instance_source);
    REQUIRE(many.triangle_normals.size() == one.triangle_normals.size());
    CHECK(std::memcmp(many.triangle_normals.data(), one.triangle_normals.data(),
                      one.triangle_normals.size() * sizeof(dev::TriangleNormals)) == 0);
  }
  check_scene_bvh(scene, one);
}

// A partition's test that counts how many items went each way and the largest value each way.
struct SeenSides {
  unsigned percent_left;
  std::size_t count[2] = {0, 0};
  std::uint32_t largest[2] = {0, 0};
  bool operator()(std::uint32_t v) {
    const bool left = (v & 0xff) < percent_left;
    ++count[left ? 0 : 1];
    largest[left ? 0 : 1] = std::max(largest[left ? 0 : 1], v);
    return left;
  }
  SeenSides part() const { return {percent_left}; }
  void merge(const SeenSides& s) {
    for (int k = 0; k < 2; ++k) {
      count[k] += s.count[k];
      largest[k] = std::max(largest[k], s.largest[k]);
    }
  }
};

TEST_CASE("a large range is partitioned in exactly std::partition's order", "[bvh]") {
  std::mt19937 rng(5);
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{7}, 2 * kParallelBlock - 1,
                        2 * kParallelBlock, std::size_t{100001}, 5 * kParallelBlock + 3}) {
    for (unsigned percent_left : {0u, 1u, 10u, 50u, 99u, 100u}) {
      std::vector<std::uint32_t> input(n);
      for (std::uint32_t& v : input) v = static_cast<std::uint32_t>(rng() % 100) | static_cast<std::uint32_t>(rng()) << 8;
      std::vector<std::uint32_t> expected = input;
      const auto left = [percent_left](std::uint32_t v) { return (v & 0xff) < percent_left; };
      const auto expected_middle = std::partition(expected.begin(), expected.end(), left) - expected.begin();
      SeenSides expected_seen{percent_left};
      for (std::uint32_t v : input) expected_seen(v);
      for (unsigned threads : {1u, 2u, 7u}) {
        INFO(n << " items, " << percent_left << "% to the left, " << threads << " threads");
        parallel_thread_limit = threads;
        std::vector<std::uint32_t> values = input;
        SeenSides seen{percent_left};
        const auto middle = partition_like_std(values.data(), values.data() + n, seen) - values.data();
        parallel_thread_limit = 0;
        CHECK(middle == expected_middle);
        CHECK(values == expected);
        // Each item is seen once when the range is partitioned in blocks.
        if (n >= 2 * kParallelBlock) {
          CHECK(seen.count[0] == expected_seen.count[0]);
          CHECK(seen.count[1] == expected_seen.count[1]);
        }
        CHECK(seen.largest[0] == expected_seen.largest[0]);
        CHECK(seen.largest[1] == expected_seen.largest[1]);
      }
    }
  }
}

TEST_CASE("boxes beyond the float range: finite centres, SAH splits, no NaN anywhere", "[bvh]") {
  const float big = std::numeric_limits<float>::max() * 0.9f, inf = Box::kInf;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  SECTION("padded world boxes of huge or undefined extents are infinite, not NaN") {
    const Box huge = padded_world_box({-9e125, 0, 0}, {9e125, 1, 1});
    CHECK(huge.lo[0] == -inf);
    CHECK(huge.hi[0] == inf);
    CHECK(huge.lo[1] < 0);
    CHECK(huge.hi[1] > 1);
    const Box undefined = padded_world_box({std::nan(""), 0, 0}, {1, 1, 1});
    CHECK(undefined.lo[0] == -inf);
    CHECK(undefined.hi[0] == inf);
  }
  SECTION("every item has a finite centre") {
    std::vector<Box> boxes(4);
    boxes[0].grow(-inf, 0, 0);
    boxes[0].grow(inf, 1, 1);
    boxes[1].grow(big, big, big);  // lo + hi overflows
    boxes[2].grow(-big, 0, 0);
    boxes[2].grow(-big, 1, nan);  // the NaN is not taken in
    for (const BuildItem& item : make_build_items(boxes, {}))
      for (int a = 0; a < 3; ++a) {
        INFO("item " << item.index << " axis " << a);
        CHECK(std::isfinite(item.center(a)));
      }
    CHECK(make_build_items(boxes, {})[1].center(0) == big);
  }
  SECTION("two clusters further apart than the largest float are split apart") {
    std::mt19937 rng(3);
    std::vector<Box> boxes;
    for (int i = 0; i < 64; ++i) {
      const float x = i % 2 ? big : -big, y = static_cast<float>(rng() % 1000), z = static_cast<float>(rng() % 1000);
      Box b;
      b.grow(x, y, z);
      b.grow(x, y + 1, z + 1);
      boxes.push_back(b);
    }
    const BvhTree tree = build_bvh(boxes, BvhBuildSettings{});
    for (const BvhLane& lane : tree.nodes.at(0).lane) {
      if (lane.count == 0 && lane.node < 0) continue;
      INFO("lane from " << lane.box.lo[0] << " to " << lane.box.hi[0]);
      CHECK((lane.box.hi[0] < 0 || lane.box.lo[0] > 0));
    }
  }
  SECTION("a sphere scaled by 9e125 among ordinary ones") {
    Scene scene;
    scene.materials.resize(1);
    scene.instances.push_back(place_instance(ShapeKind::Sphere, Mat4::scale({9e125, 9e125, 9e125})));
    std::mt19937 rng(4);
    for (int i = 0; i < 100; ++i)
      scene.instances.push_back(place_instance(ShapeKind::Sphere, random_similarity(rng, 10, 0.1, 1)));
    scene.instances.push_back(place_instance(ShapeKind::Cube, Mat4::translate({1e30, 0, 0}) * Mat4::scale({1e10, 1, 1})));
    const GeometryData g = build_geometry(scene);
    std::vector<std::uint32_t> blocks{0};
    while (!blocks.empty()) {
      const dev::BvhNode node = node_at(g.nodes, blocks.back());
      blocks.pop_back();
      for (int k = 0; k < CLRT_BVH_WIDTH; ++k) {
        if (node.child[k] == CLRT_BVH_EMPTY_LANE) continue;
        const Box b = lane_box(node, k);
        for (int a = 0; a < 3; ++a) CHECK_FALSE((std::isnan(b.lo[a]) || std::isnan(b.hi[a])));
        if (node.child[k] >= 0) blocks.push_back(static_cast<std::uint32_t>(node.child[k]));
      }
    }
    check_scene_bvh(scene, g);
  }
}

TEST_CASE("once the geometry is built the meshes' data can be freed", "[bvh]") {
  Scene scene;
  scene.meshes.push_back(ball_mesh(6, 8, true));
  scene.meshes.back().path = "ball.obj";
  scene.instances.push_back(place_instance(ShapeKind::Mesh, Mat4::translate({1, 0, 0})));
  scene.instances.back().mesh = 0;
  const GeometryData before = build_geometry(scene);
  release_mesh_data(scene);
  const MeshData& m = scene.meshes.at(0);
  CHECK(m.path == "ball.obj");
  CHECK(m.positions.capacity() == 0);
  CHECK(m.normals.capacity() == 0);
  CHECK(m.corners.capacity() == 0);
  CHECK(m.corner_normals.capacity() == 0);
  CHECK(before.triangle_count() == 6 * 8 * 2);
}

TEST_CASE("texture coordinate rows follow each mesh's leaf order, only for meshes that have them", "[bvh]") {
  Scene scene;
  scene.meshes.push_back(ball_mesh(6, 8, false));  // (u, v) per corner from its position
  scene.meshes.push_back(ball_mesh(5, 7, false));  // none
  MeshData& textured = scene.meshes[0];
  for (const Vec3& p : textured.positions) textured.texcoords.push_back({static_cast<float>(p.x), static_cast<float>(p.y)});
  textured.corner_texcoords = textured.corners;
  for (std::size_t c = 0; c < 3; ++c) textured.corner_texcoords[c] = kNoMeshTexcoord;  // triangle 0 has none
  for (int m = 0; m < 2; ++m) {
    scene.instances.push_back(place_instance(ShapeKind::Mesh, Mat4::translate({3.0 * m, 0, 0})));
    scene.instances.back().mesh = m;
  }
  TriangleSpec loose{{0, 0, 5}, {1, 0, 5}, {0, 1, 5}, 0};
  scene.triangles.push_back(loose);
  loose.uv = {0.5f, 0.25f, 2, 3, -1, 4};
  loose.has_uv = true;
  scene.triangles.push_back(loose);
  const GeometryData g = build_geometry(scene);
  REQUIRE(g.meshes.size() == 3);
  CHECK(g.meshes[1].texcoords == CLRT_NO_TEXCOORDS);
  const std::size_t balls = textured.corners.size() / 3;
  CHECK(g.meshes[0].texcoords == 0);
  CHECK(g.meshes[2].texcoords == balls);
  REQUIRE(g.triangle_texcoords.size() == balls + 2);
  for (std::size_t m : {std::size_t{0}, std::size_t{2}})
    for (std::uint32_t i = 0; i < g.meshes[m].triangle_count; ++i) {
      const std::uint32_t t = g.triangle_source[g.meshes[m].first_triangle + i];
      const dev::TriangleTexcoords& row = g.triangle_texcoords[g.meshes[m].texcoords + i];
      for (int k = 0; k < 3; ++k) {
        INFO("mesh " << m << ", triangle " << t << ", corner " << k);
        float u = k == 1 ? 1.0f : 0.0f, v = k == 2 ? 1.0f : 0.0f;  // the default
        if (m == 0 && t != 0) {
          const Vec3& p = textured.positions[textured.corners[3 * t + static_cast<std::size_t>(k)]];
          u = static_cast<float>(p.x);
          v = static_cast<float>(p.y);
        } else if (m == 2 && scene.triangles[t].has_uv) {
          u = scene.triangles[t].uv[static_cast<std::size_t>(2 * k)];
          v = scene.triangles[t].uv[static_cast<std::size_t>(2 * k + 1)];
        }
        CHECK(row.uv[2 * k] == u);
        CHECK(row.uv[2 * k + 1] == v);
      }
    }
  // A build for a render makes the same rows and frees the mesh's coordinates.
  const GeometryData freed = build_geometry_for_render(scene);
  CHECK(std::memcmp(freed.triangle_texcoords.data(), g.triangle_texcoords.data(),
                    sizeof(dev::TriangleTexcoords) * g.triangle_texcoords.size()) == 0);
  CHECK(scene.meshes[0].texcoords.capacity() == 0);
  CHECK(scene.meshes[0].corner_texcoords.capacity() == 0);
}

TEST_CASE("a build for a render frees the meshes and instances as it goes and makes the same tables", "[bvh]") {
  Scene scene;
  scene.meshes.push_back(ball_mesh(6, 8, true));   // with normals: freed after the rows
  scene.meshes.push_back(ball_mesh(5, 7, false));  // without
  // Spheres and a cube first, so that the top level reorders the instances: mesh 0, placed alone
  // with the identity, is entered straight from the top level, wherever its instance goes.
  for (int i = 0; i < 40; ++i)
    scene.instances.push_back(place_instance(ShapeKind::Sphere, Mat4::translate({0.5 * i, 2, 1.0 * (i % 3)}) *
                                                                    Mat4::scale({0.2, 0.2, 0.2})));
  scene.instances.push_back(place_instance(ShapeKind::Cube, Mat4::rotate(30, {0, 1, 0})));
  for (int m = 0; m < 2; ++m) {
    scene.meshes[static_cast<std::size_t>(m)].path = "ball" + std::to_string(m) + ".obj";
    scene.instances.push_back(place_instance(ShapeKind::Mesh, Mat4::translate({3.0 * m, 0, 0})));
    scene.instances.back().mesh = m;
  }
  scene.triangles.push_back({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}, 0});
  const GeometryData kept = build_geometry(scene);
  check_scene_bvh(scene, kept);
  const GeometryData freed = build_geometry_for_render(scene);
  const auto same_bytes = [](const auto& a, const auto& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(a[0]) * a.size()) == 0;
  };
  CHECK(same_bytes(kept.nodes, freed.nodes));
  CHECK(same_bytes(kept.triangle_normals, freed.triangle_normals));
  CHECK(same_bytes(kept.triangle_materials, freed.triangle_materials));
  CHECK(same_bytes(kept.instances, freed.instances));
  CHECK(same_bytes(kept.meshes, freed.meshes));
  CHECK(kept.triangle_source.size() == kept.triangle_count());
  CHECK(freed.triangle_source.empty());
  CHECK(freed.instance_source.empty());
  for (const MeshData& m : scene.meshes) {
    CHECK(m.path.rfind("ball", 0) == 0);
    CHECK(m.positions.capacity() == 0);
    CHECK(m.normals.capacity() == 0);
    CHECK(m.corner_normals.capacity() == 0);
  }
  CHECK(scene.triangles.size() == 1);
  CHECK(scene.instances.empty());
}
