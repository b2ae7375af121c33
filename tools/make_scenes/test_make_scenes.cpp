// The generator at scale 0.001: every scene loads with clrt's own loader and holds the counts
// worked out by hand below; the knot is a closed, consistently wound tube; output is
// deterministic.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "large_scenes.hpp"
#include "scene/scene.hpp"
#include "torus_knot.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kScale = 0.001;

// Each test case writes its own folder: ctest may run them at the same time.
fs::path fresh_folder(const std::string& name) {
  const fs::path folder = fs::path(CLRT_BINARY_DIR) / "make-scenes-test" / name;
  fs::remove_all(folder);
  clrt::scenes::write_large_scenes(folder.string(), kScale);
  return folder;
}

clrt::Scene load(const fs::path& folder, const std::string& name) {
  return clrt::load_scene((folder / name).string());
}

int count_shapes(const clrt::Scene& scene, clrt::ShapeKind kind) {
  int n = 0;
  for (const clrt::InstanceSpec& i : scene.instances) n += i.shape == kind;
  return n;
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("knot grids are chosen near the asked triangle count") {
  // sqrt(1e6 / 16) = 250 around, 1e6 / 500 = 2000 along.
  CHECK(clrt::scenes::knot_grid_for(1000000).triangles() == 1000000);
  // sqrt(1000 / 16) = 7.9 -> 8 around; 1000 / 16 = 62.5 -> 63 along: 2 * 8 * 63.
  CHECK(clrt::scenes::knot_grid_for(1000).triangles() == 1008);
  // 100 -> 2.5 -> 3 around (at least 3 anyway); 100 / 6 = 16.7 -> 17 along.
  CHECK(clrt::scenes::knot_grid_for(100).triangles() == 102);
  CHECK(clrt::scenes::knot_grid_for(1).triangles() == 18);
}

TEST_CASE("the galaxy has 100 spheres (at scale 0.001), a floor, two lights") {
  const clrt::Scene scene = load(fresh_folder("galaxy"), "spheres-100k.ray");
  CHECK(count_shapes(scene, clrt::ShapeKind::Sphere) == 100);
  CHECK(count_shapes(scene, clrt::ShapeKind::Plane) == 1);
  CHECK(scene.instances.size() == 101);
  CHECK(scene.lights.size() == 2);
  CHECK(scene.width == 800);
  CHECK(scene.height == 600);
}

TEST_CASE("each scene has the instances and triangles its scaled counts give") {
  // name -> {mesh instances, triangles per mesh}; 0.001 of 100 instances rounds to 0 -> 1.
  const std::map<std::string, std::pair<int, std::size_t>> expected = {
      {"mesh-1m-x100.ray", {1, 1008}}, {"tri-1k.ray", {1, 18}},   {"tri-10k.ray", {1, 18}},
      {"tri-100k.ray", {1, 102}},      {"tri-1m.ray", {1, 1008}}, {"inst-10.ray", {1, 18}},
      {"inst-100.ray", {1, 18}},       {"inst-1k.ray", {1, 18}},  {"inst-10k.ray", {10, 18}},
      {"inst-100k.ray", {100, 18}}};
  const fs::path folder = fresh_folder("counts");
  for (const auto& [name, counts] : expected) {
    INFO(name);
    const clrt::Scene scene = load(folder, name);
    CHECK(count_shapes(scene, clrt::ShapeKind::Mesh) == counts.first);
    REQUIRE(scene.meshes.size() == 1);
    CHECK(scene.meshes[0].corners.size() == 3 * counts.second);
    CHECK(scene.meshes[0].normals.size() == scene.meshes[0].positions.size());
  }
}

TEST_CASE("the knot is a closed tube wound counter-clockwise seen from outside") {
  const clrt::MeshData mesh = load(fresh_folder("knot"), "tri-1m.ray").meshes.at(0);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed_edges;
  for (std::size_t k = 0; k < mesh.corners.size(); k += 3) {
    const std::uint32_t v[3] = {mesh.corners[k], mesh.corners[k + 1], mesh.corners[k + 2]};
    for (int e = 0; e < 3; ++e) ++directed_edges[{v[e], v[(e + 1) % 3]}];
    const clrt::Vec3 face = cross(mesh.positions[v[1]] - mesh.positions[v[0]],
                                  mesh.positions[v[2]] - mesh.positions[v[0]]);
    for (std::uint32_t corner : v) {
      INFO("triangle " << k / 3);
      CHECK(dot(face, mesh.normals[mesh.corner_normals[k]]) > 0);
      const clrt::Vec3 p = mesh.positions[corner];
      CHECK(std::abs(p.x) < clrt::scenes::kKnotHalfWidth);
      CHECK(std::abs(p.z) < clrt::scenes::kKnotHalfWidth);
      CHECK(std::abs(p.y) < clrt::scenes::kKnotHalfHeight);
    }
  }
  // Closed and consistently wound: every edge is walked once each way.
  for (const auto& [edge, uses] : directed_edges) {
    CHECK(uses == 1);
    CHECK(directed_edges.count({edge.second, edge.first}) == 1);
  }
}

TEST_CASE("the same scale writes the same bytes") {
  const fs::path first = fresh_folder("first"), again = fresh_folder("again");
  for (const auto& entry : fs::directory_iterator(first)) {
    INFO(entry.path().filename());
    CHECK(contents(entry.path()) == contents(again / entry.path().filename()));
  }
}
