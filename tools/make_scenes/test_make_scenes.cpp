// The generator at scale 0.001: every scene loads with clrt's own loader and holds the counts
// worked out by hand below; the knot is a closed, consistently wound tube; output is
// deterministic.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>

#include "knob_scenes.hpp"
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

namespace {

// The lobe subset a knob material reads as in path mode (docs/path-tracing.md, "Materials"):
// a lobe is present when its weight is not zero, and each present one carries 0.9 / present.
unsigned lobes_of(const clrt::MaterialSpec& m) {
  using namespace clrt::scenes;
  const double share = std::max(0.0, 1 - m.kr - m.kt);
  const double colour = std::max({m.color.x, m.color.y, m.color.z});
  const double weights[4] = {share * m.kd * colour, share * m.ks, m.kr, m.kt};
  const unsigned bits[4] = {kLambert, kPhong, kMirror, kDielectric};
  unsigned lobes = 0;
  int present = 0;
  for (int l = 0; l < 4; ++l) present += weights[l] > 0;
  for (int l = 0; l < 4; ++l) {
    if (weights[l] == 0) continue;
    lobes |= bits[l];
    CHECK(std::abs(weights[l] - 0.9 / present) < 1e-6);
  }
  if (m.kt > 0) CHECK(m.ior == 1.5);
  return lobes;
}

std::vector<clrt::Vec3> sphere_centres(const clrt::Scene& scene) {
  std::vector<clrt::Vec3> centres;
  for (const clrt::InstanceSpec& i : scene.instances)
    if (i.shape == clrt::ShapeKind::Sphere) centres.push_back(i.transform.transform_point({}));
  std::sort(centres.begin(), centres.end(), [](const clrt::Vec3& a, const clrt::Vec3& b) {
    return std::tie(a.x, a.z) < std::tie(b.x, b.z);
  });
  return centres;
}

}  // namespace

TEST_CASE("knob scene k spreads the k cheapest lobe subsets in equal shares over one grid") {
  const fs::path folder = fs::path(CLRT_BINARY_DIR) / "make-scenes-test" / "knob";
  fs::remove_all(folder);
  const std::vector<std::string> files = clrt::scenes::write_knob_scenes(folder.string(), 0.05);
  CHECK(files.size() == 32);
  const std::vector<unsigned>& order = clrt::scenes::knob_lobe_order();
  REQUIRE(order.size() == 16);
  CHECK(std::set<unsigned>(order.begin(), order.end()).size() == 16);  // every subset once
  // 0.05 of 576 spheres is 28.8, a 6 x 6 grid.
  REQUIRE(clrt::scenes::knob_grid_side(0.05) == 6);
  const std::vector<clrt::Vec3> grid = sphere_centres(load(folder, "knob-01.ray"));
  REQUIRE(grid.size() == 36);
  for (std::size_t k = 1; k <= 16; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "knob-%02zu.ray", k);
    INFO(name);
    const clrt::Scene scene = load(folder, name);
    CHECK(sphere_centres(scene) == grid);
    CHECK(count_shapes(scene, clrt::ShapeKind::Plane) == 1);
    std::map<unsigned, int> spheres_of;
    for (const clrt::InstanceSpec& i : scene.instances)
      if (i.shape == clrt::ShapeKind::Sphere) ++spheres_of[lobes_of(scene.materials.at(i.material))];
    CHECK(spheres_of.size() == k);
    for (std::size_t m = 0; m < k; ++m) {
      INFO("subset " << clrt::scenes::lobe_letters(order[m]));
      CHECK(spheres_of.count(order[m]) == 1);
      // 36 spheres in k shares: each share is 36 / k rounded down or up.
      CHECK(spheres_of[order[m]] >= static_cast<int>(36 / k));
      CHECK(spheres_of[order[m]] <= static_cast<int>((36 + k - 1) / k));
    }
  }
  for (const unsigned lobes : order) {
    const std::string name = "knob-lobes-" + clrt::scenes::lobe_letters(lobes) + ".ray";
    INFO(name);
    const clrt::Scene scene = load(folder, name);
    CHECK(sphere_centres(scene) == grid);
    for (const clrt::InstanceSpec& i : scene.instances)
      if (i.shape == clrt::ShapeKind::Sphere) CHECK(lobes_of(scene.materials.at(i.material)) == lobes);
  }
}

TEST_CASE("texture knob scene k spreads the first k textured materials in equal shares over one grid") {
  const fs::path folder = fs::path(CLRT_BINARY_DIR) / "make-scenes-test" / "texture-knob";
  fs::remove_all(folder);
  const std::vector<clrt::scenes::TextureKnobEntry>& order = clrt::scenes::texture_knob_order();
  REQUIRE(order.size() == 8);
  const std::vector<std::string> files = clrt::scenes::write_texture_knob_scenes(folder.string(), 0.05);
  CHECK(files.size() == 4 + 2 * order.size());  // the images, then the scenes
  const std::vector<clrt::Vec3> grid = sphere_centres(load(folder, "texture-knob-1.ray"));
  REQUIRE(grid.size() == 36);
  // A material's textures as the kinds and image sizes they show, which tell the entries apart.
  const auto signature = [](const clrt::Scene& scene, const clrt::MaterialSpec& m) {
    std::string s;
    for (int t : m.textures) {
      if (t < 0) continue;
      const clrt::TextureSpec& spec = scene.textures.at(static_cast<std::size_t>(t));
      s += std::to_string(static_cast<int>(spec.kind)) + "/" + std::to_string(spec.octaves);
      if (spec.image >= 0) {
        const clrt::TextureImage& image = scene.texture_images.at(static_cast<std::size_t>(spec.image));
        s += "/" + std::to_string(image.width) + (image.linear ? "f" : "b");
      }
      s += ";";
    }
    return s;
  };
  std::vector<std::string> signatures;
  for (const clrt::scenes::TextureKnobEntry& e : order) {
    const clrt::Scene only = load(folder, "texture-knob-only-" + e.name + ".ray");
    CHECK(sphere_centres(only) == grid);
    std::set<std::string> seen;
    for (const clrt::InstanceSpec& i : only.instances)
      if (i.shape == clrt::ShapeKind::Sphere) seen.insert(signature(only, only.materials.at(i.material)));
    REQUIRE(seen.size() == 1);
    signatures.push_back(*seen.begin());
  }
  CHECK(std::set<std::string>(signatures.begin(), signatures.end()).size() == order.size());
  CHECK(signatures.front().empty());  // the plain material
  for (std::size_t k = 1; k <= order.size(); ++k) {
    INFO("texture-knob-" << k);
    const clrt::Scene scene = load(folder, "texture-knob-" + std::to_string(k) + ".ray");
    CHECK(sphere_centres(scene) == grid);
    std::map<std::string, int> spheres_of;
    for (const clrt::InstanceSpec& i : scene.instances)
      if (i.shape == clrt::ShapeKind::Sphere) ++spheres_of[signature(scene, scene.materials.at(i.material))];
    CHECK(spheres_of.size() == k);
    for (std::size_t m = 0; m < k; ++m) {
      CHECK(spheres_of[signatures[m]] >= static_cast<int>(36 / k));
      CHECK(spheres_of[signatures[m]] <= static_cast<int>((36 + k - 1) / k));
    }
  }
}
