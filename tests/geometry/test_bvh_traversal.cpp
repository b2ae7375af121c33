// scene_closest_hit and scene_any_hit through the BVH against a double-precision brute force.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <sstream>

#include "bvh_reference.hpp"
#include "bvh_test_device.hpp"
#include "bvh_test_scenes.hpp"
#include "geometry/geometry_data.hpp"

using namespace clrt;
using namespace clrt::bvhtest;

namespace {

std::string describe(const TestRay& r) {
  std::ostringstream out;
  out.precision(9);
  out << "o=(" << r.o.x << ", " << r.o.y << ", " << r.o.z << ") d=(" << r.d.x << ", " << r.d.y
      << ", " << r.d.z << ") tmin=" << r.tmin << " tmax=" << r.tmax;
  return out.str();
}

struct Tally {
  int compared = 0, ambiguous = 0, hits = 0;
  std::vector<std::string> mismatches;

  void mismatch(const TestRay& r, const std::string& what) {
    if (mismatches.size() < 5) mismatches.push_back(what + " for " + describe(r));
  }

  void check(std::size_t rays) const {
    INFO((mismatches.empty() ? std::string() : mismatches.front()));
    CHECK(mismatches.empty());
    // The comparison is only worth something when it covers most rays, many of them hits.
    CHECK(ambiguous * 20 < static_cast<int>(rays));
    CHECK(hits * 5 > compared);
  }
};

void compare_closest(const Scene& scene, const std::vector<TestRay>& rays) {
  const GeometryData g = build_geometry(scene);
  const std::vector<dev::Hit> hits = device_closest_hits(g, rays);
  Tally tally;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const TestRay& r = rays[i];
    const ReferenceResult ref = reference_closest_hit(scene, r.o, r.d, r.tmin, r.tmax);
    if (ref.ambiguous) {
      ++tally.ambiguous;
      continue;
    }
    ++tally.compared;
    const bool hit = hits[i].instance != CLRT_NO_HIT;
    if (hit != ref.hit) {
      tally.mismatch(r, ref.hit ? "missed" : "false hit");
      continue;
    }
    if (!hit) continue;
    ++tally.hits;
    const ObjectId got = hit_object(g, hits[i]);
    if (!(got == ref.object))
      tally.mismatch(r, "hit instance " + std::to_string(got.instance) + " triangle " +
                            std::to_string(got.triangle) + " instead of " +
                            std::to_string(ref.object.instance) + "/" + std::to_string(ref.object.triangle));
    else if (std::fabs(hits[i].geometric_normal.w - ref.t) > t_tolerance(ref.t))
      tally.mismatch(r, "t " + std::to_string(hits[i].geometric_normal.w) + " instead of " +
                            std::to_string(ref.t));
  }
  tally.check(rays.size());
}

void compare_any(const Scene& scene, const std::vector<TestRay>& rays) {
  const std::vector<int> any = device_any_hits(build_geometry(scene), rays);
  Tally tally;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const ReferenceResult ref = reference_closest_hit(scene, rays[i].o, rays[i].d, rays[i].tmin, rays[i].tmax);
    if (ref.ambiguous) {
      ++tally.ambiguous;
      continue;
    }
    ++tally.compared;
    tally.hits += ref.hit;
    if ((any[i] != 0) != ref.hit) tally.mismatch(rays[i], ref.hit ? "any-hit missed" : "any-hit false hit");
  }
  tally.check(rays.size());
}

}  // namespace

TEST_CASE("closest hits through the BVH match a brute force on random scenes", "[bvh][device]") {
  for (int objects : {100, 200, 300}) {
    const unsigned seed = static_cast<unsigned>(objects);
    std::mt19937 rng(seed);
    const Scene scene = random_scene(rng, objects, 200);
    INFO("seed " << seed);
    compare_closest(scene, random_rays(rng, scene, 3000));
  }
}

TEST_CASE("any hits through the BVH match a brute force on random scenes", "[bvh][device]") {
  for (unsigned seed : {21u, 22u}) {
    std::mt19937 rng(seed);
    const Scene scene = random_scene(rng, 150, 150);
    INFO("seed " << seed);
    std::vector<TestRay> rays = random_rays(rng, scene, 3000);
    for (std::size_t i = 0; i < rays.size(); i += 3) rays[i].tmin = 1e-4;
    compare_any(scene, rays);
  }
}

TEST_CASE("hits in a scene of loose triangles alone (the top level is their mesh's) match a brute force",
          "[bvh][device]") {
  std::mt19937 rng(41);
  const Scene full = random_scene(rng, 0, 600);
  std::vector<TestRay> rays = random_rays(rng, full, 3000);
  Scene scene;
  scene.materials = full.materials;
  scene.triangles = full.triangles;
  compare_closest(scene, rays);
  for (std::size_t i = 0; i < rays.size(); i += 3) rays[i].tmin = 1e-4;
  compare_any(scene, rays);
}

TEST_CASE("closest and any hits through sphere packets match a brute force", "[bvh][device]") {
  for (unsigned seed : {31u, 32u}) {
    std::mt19937 rng(seed);
    const Scene scene = sphere_scene(rng, 400);
    INFO("seed " << seed);
    std::vector<TestRay> rays = random_rays(rng, scene, 3000);
    compare_closest(scene, rays);
    for (std::size_t i = 0; i < rays.size(); i += 3) rays[i].tmin = 1e-4;
    compare_any(scene, rays);
  }
}
