// shadow (kernels/shadow.cl) launched alone on hand-made shadow rays against a small scene: a
// sphere of radius 0.5 centred at (0, 2, 0) and the plane y = -5. The contract: a shadow ray
// towards a point at distance d is blocked by a hit with epsilon <= t < d; towards a
// directional light (d infinite) by any hit with t >= epsilon.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <limits>
#include <vector>

#include "cl_fixture.hpp"
#include "geometry/device_geometry.hpp"
#include "geometry/geometry_data.hpp"
#include "render/frame_setup.hpp"
#include "render/stage_args.hpp"
#include "shared/ray.h"
#include "test_vectors.hpp"

using namespace clrt;
using test::f4_of;
using test::vec_of;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Scene blocker_scene() {
  Scene scene;
  scene.materials.resize(1);
  scene.instances.push_back(
      place_instance(ShapeKind::Sphere, Mat4::translate({0, 2, 0}) * Mat4::scale({0.5, 0.5, 0.5})));
  scene.instances.push_back(place_instance(ShapeKind::Plane, Mat4::translate({0, -5, 0})));
  return scene;
}

struct Probe {
  const char* what;
  Vec3 origin, dir;
  double tmax;  // distance to the light; infinite for a directional light
  bool blocked;
};

const std::vector<Probe> kProbes = {
    {"blocker before a point light", {0, 0, 0}, {0, 1, 0}, 3, true},
    {"light before the blocker", {0, 0, 0}, {0, 1, 0}, 1.4, false},
    {"light just past the sphere's surface", {0, 0, 0}, {0, 1, 0}, 1.501, true},
    {"light just short of the sphere's surface", {0, 0, 0}, {0, 1, 0}, 1.499, false},
    {"directional light behind the sphere", {0, 0, 0}, {0, 1, 0}, kInf, true},
    {"directional light behind the far plane", {0, 0, 0}, {0, -1, 0}, kInf, true},
    {"point light short of the plane", {0, 0, 0}, {0, -1, 0}, 4.9, false},
    {"point light past the plane", {0, 0, 0}, {0, -1, 0}, 5.1, true},
    {"nothing along the ray", {0, 0, 0}, {1, 0, 0}, kInf, false},
    {"blocker behind the origin", {0, 3, 0}, {0, 1, 0}, kInf, false},
    {"leaving the sphere's top: its own surface is ignored", {0, 2.5, 0}, {0, 1, 0}, kInf, false},
    {"entering the sphere at its top: blocked by its far side", {0, 2.5, 0}, {0, -1, 0}, 2, true},
    {"sideways through the sphere", {3, 2, 0}, {-1, 0, 0}, kInf, true},
    {"sideways just above the sphere", {3, 2.6, 0}, {-1, 0, 0}, kInf, false},
    {"a hit nearer than epsilon is ignored", {4, -5 + 0.5e-4, 0}, {0, -1, 0}, kInf, false},
    {"a hit just beyond epsilon blocks", {4, -5 + 2e-4, 0}, {0, -1, 0}, kInf, true},
    // Through the sphere's centre, entering it at t = sqrt(2) - 0.5 = 0.914.
    {"slanted towards a point light past the sphere", {-1, 1, 0}, normalize({1, 1, 0}), 1, true},
    {"slanted towards a point light short of the sphere", {-1, 1, 0}, normalize({1, 1, 0}), 0.85,
     false},
};

std::vector<dev::f4> run_shadow(const Scene& scene, const std::vector<dev::ShadowRay>& shadows) {
  const DeviceGeometry device_geometry(test::device(),
                                       std::make_shared<const GeometryData>(build_geometry(scene)));
  const auto count = static_cast<cl_uint>(shadows.size());
  ShadowArgs args;
  args.scene = device_geometry.args();
  args.params = test::upload(std::vector<dev::RenderParams>{make_params(scene, RenderOptions{})});
  args.shadows = test::upload(shadows);
  args.count = test::upload(std::vector<cl_uint>{count});
  args.visible = test::upload(std::vector<dev::f4>(shadows.size(), dev::f4{-1, -1, -1, -1}));
  // Launched over more work-items than the queue holds, as the renderer does: the count on the
  // device bounds the work.
  test::run(test::renderer_program(), args, count + 100);
  return test::download(args.visible, count);
}

}  // namespace

TEST_CASE("shadow: any hit between epsilon and the light blocks", "[shadow]") {
  // Every probe five times over, so the queue spans several work-groups and ends mid-group.
  std::vector<dev::ShadowRay> queue;
  for (int round = 0; round < 5; ++round) {
    for (const Probe& p : kProbes) {
      dev::ShadowRay s{};
      s.origin = f4_of(p.origin, p.tmax);
      s.dir = f4_of(p.dir);
      const double k = static_cast<double>(queue.size());
      s.contribution = f4_of({k + 1, 0.5 * k, 0.25});
      s.owner = static_cast<dev::u32>(queue.size());
      queue.push_back(s);
    }
  }
  const std::vector<dev::f4> visible = run_shadow(blocker_scene(), queue);
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const Probe& p = kProbes[i % kProbes.size()];
    INFO(p.what);
    const Vec3 expected = p.blocked ? Vec3{} : vec_of(queue[i].contribution);
    CHECK_NEAR_VEC(vec_of(visible[i]), expected, 0);
  }
}
