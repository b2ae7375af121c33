// The comparison's parts on a scene small enough to work out by hand: both tracers must give
// the hand-computed answers, the rays must be the ones the contract defines, and the
// agreement measure must reject what it should.
#include <catch2/catch.hpp>
#include <cmath>

#include "agreement.hpp"
#include "clrt_tracer.hpp"
#include "device/device_select.hpp"
#include "embree_scene.hpp"
#include "geometry/geometry_data.hpp"
#include "host_rays.hpp"
#include "render/renderer.hpp"
#include "render/renderer_program.hpp"
#include "whitted_tracer.hpp"

namespace {

using clrt::Mat4;
using clrt::ShapeKind;
using clrt::Vec3;
using clrt::compare::HostRay;

clrt::InstanceSpec placed(ShapeKind shape, const Mat4& m, int mesh = -1) {
  clrt::InstanceSpec i = clrt::place_instance(shape, m);
  i.mesh = mesh;
  return i;
}

// A sphere of radius 2 about (0, 0, -10), turned; the plane y = -1; a loose triangle across
// the +z axis at z = 5; a one-triangle mesh across the +x axis at x = 3, scaled by 2 (x = 6).
clrt::Scene hand_scene() {
  clrt::Scene scene;
  scene.materials.resize(1);
  scene.instances.push_back(
      placed(ShapeKind::Sphere,
             Mat4::translate({0, 0, -10}) * Mat4::rotate(30, {1, 1, 0}) * Mat4::scale({2, 2, 2})));
  scene.instances.push_back(placed(ShapeKind::Plane, Mat4::translate({0, -1, 0})));
  scene.triangles.push_back({{-1, -1, 5}, {1, -1, 5}, {0, 1, 5}, 0});
  clrt::MeshData mesh;
  mesh.positions = {{3, -1, -1}, {3, 1, -1}, {3, 0, 1}};
  mesh.corners = {0, 1, 2};
  scene.meshes.push_back(mesh);
  scene.instances.push_back(placed(ShapeKind::Mesh, Mat4::scale({2, 2, 2}), 0));
  return scene;
}

HostRay ray(const Vec3& o, const Vec3& d, float tmax = INFINITY) {
  const Vec3 u = normalize(d);
  return {{float(o.x), float(o.y), float(o.z)}, {float(u.x), float(u.y), float(u.z)}, tmax};
}

// Rays from the origin with their closest t: the sphere's near side, the plane, the loose
// triangle, the mesh, nothing; and from the sphere's centre, its far side.
const std::vector<std::pair<HostRay, float>> kClosest = {
    {ray({0, 0, 0}, {0, 0, -1}), 8.0f},     {ray({0, 0, 0}, {0, -1, 0}), 1.0f},
    {ray({0, 0, 0}, {0, 0, 1}), 5.0f},      {ray({0, 0, 0}, {1, 0, 0}), 6.0f},
    {ray({0, 0, 0}, {-1, 0, 0}), INFINITY}, {ray({0, 0, -10}, {0, 1, 0}), 2.0f}};

// Shadow rays: blocked only when tmax lies beyond the first surface.
const std::vector<std::pair<HostRay, bool>> kOcclusion = {
    {ray({0, 0, 0}, {0, 0, -1}, 7.9f), false}, {ray({0, 0, 0}, {0, 0, -1}, 8.1f), true},
    {ray({0, 0, 0}, {0, -1, 0}, 0.9f), false}, {ray({0, 0, 0}, {0, -1, 0}, 1.1f), true},
    {ray({0, 0, 0}, {1, 0, 0}, 5.9f), false},  {ray({0, 0, 0}, {1, 0, 0}, 6.1f), true},
    {ray({0, 0, 0}, {-1, 0, 0}), false}};

clrt::compare::RaySet set_of_closest() {
  clrt::compare::RaySet set{"hand", {}};
  for (const auto& [r, t] : kClosest) set.rays.push_back(r);
  return set;
}

}  // namespace

TEST_CASE("Embree is given spheres under similarity transforms only") {
  clrt::Scene scene = hand_scene();
  CHECK(clrt::compare::unsupported_shapes(scene).empty());
  scene.instances.push_back(placed(ShapeKind::Sphere, Mat4::scale({1, 2, 1})));
  scene.instances.push_back(placed(ShapeKind::Cube, Mat4::identity()));
  scene.instances.push_back(placed(ShapeKind::Cylinder, Mat4::identity()));
  scene.instances.push_back(placed(ShapeKind::Cylinder, Mat4::identity()));
  CHECK(clrt::compare::unsupported_shapes(scene) ==
        "1 cubes, 2 cylinders, 1 non-uniformly scaled spheres");
}

TEST_CASE("Embree's scene answers the hand-computed hits") {
  const clrt::Scene scene = hand_scene();
  const clrt::compare::EmbreeScene embree(scene, 1, RTC_BUILD_QUALITY_HIGH, RTC_SCENE_FLAG_NONE);
  for (const auto& [r, t] : kClosest) {
    INFO("ray towards " << r.dir[0] << " " << r.dir[1] << " " << r.dir[2]);
    if (std::isinf(t))
      CHECK(std::isinf(embree.closest_t(r)));
    else
      CHECK(embree.closest_t(r) == Approx(t).epsilon(1e-5));
  }
  for (const auto& [r, blocked] : kOcclusion) {
    INFO("tmax " << r.tmax);
    CHECK(embree.occluded(r) == blocked);
  }
  // Without the unbounded plane: sphere z in [-12, -8], triangle z = 5, mesh x = 6.
  const clrt::compare::Bounds b = embree.bounds();
  CHECK(b.lo.z == Approx(-12).epsilon(1e-4));
  CHECK(b.hi.z == Approx(5).epsilon(1e-4));
  CHECK(b.hi.x == Approx(6).epsilon(1e-4));
}

TEST_CASE("Embree's hits carry each surface's world normal and material") {
  clrt::Scene scene = hand_scene();
  scene.materials.resize(5);
  scene.instances[0].material = 1;  // the sphere
  scene.instances[1].material = 2;  // the plane
  scene.triangles[0].material = 3;
  scene.instances[2].material = 4;  // the mesh
  const clrt::compare::EmbreeScene embree(scene, 1, RTC_BUILD_QUALITY_HIGH, RTC_SCENE_FLAG_NONE);
  struct Expected {
    HostRay ray;
    Vec3 normal;
    int material;
  };
  // The sphere's near side faces +z; the plane y = -1 faces +y; the loose triangle, counter-
  // clockwise seen from +z, faces +z; the mesh's triangle, scaled by 2, faces +x.
  const std::vector<Expected> expected = {{ray({0, 0, 0}, {0, 0, -1}), {0, 0, 1}, 1},
                                          {ray({0, 0, 0}, {0, -1, 0}), {0, 1, 0}, 2},
                                          {ray({0, 0, 0}, {0, 0, 1}), {0, 0, 1}, 3},
                                          {ray({0, 0, 0}, {1, 0, 0}), {1, 0, 0}, 4}};
  for (const Expected& e : expected) {
    const clrt::compare::SurfaceHit hit = embree.closest_hit(e.ray);
    INFO("ray towards " << e.ray.dir[0] << " " << e.ray.dir[1] << " " << e.ray.dir[2]);
    CHECK(hit.material == e.material);
    CHECK(clrt::length(hit.normal - e.normal) < 1e-6);
    CHECK(clrt::length(hit.shading_normal - e.normal) < 1e-6);
  }
  CHECK(std::isinf(embree.closest_hit(ray({0, 0, 0}, {-1, 0, 0})).t));
}

TEST_CASE("clrt's kernels answer the hand-computed hits") {
  clrt::DeviceContext device(clrt::select_devices("cpu").front());
  const auto program = clrt::build_renderer_program(device, clrt::RenderMode::Trace, clrt::SceneFeatures{});
  const clrt::Scene scene = hand_scene();
  clrt::compare::ClrtTracer clrt(device, program, clrt::build_geometry(scene));

  clrt::compare::ClrtBatch closest = clrt.closest_batch(set_of_closest());
  clrt.launch(closest);
  const std::vector<clrt::dev::Hit> hits = clrt.hits(closest);
  for (std::size_t i = 0; i < kClosest.size(); ++i) {
    INFO("ray " << i);
    if (std::isinf(kClosest[i].second))
      CHECK(hits[i].instance == CLRT_NO_HIT);
    else
      CHECK(hits[i].geometric_normal.w == Approx(kClosest[i].second).epsilon(1e-5));
  }

  clrt::compare::RaySet shadows{"hand", {}};
  for (const auto& [r, blocked] : kOcclusion) shadows.rays.push_back(r);
  clrt::compare::ClrtBatch occlusion = clrt.occlusion_batch(shadows);
  clrt.launch(occlusion);
  const std::vector<char> blocked = clrt.blocked(occlusion);
  for (std::size_t i = 0; i < kOcclusion.size(); ++i) {
    INFO("ray " << i);
    CHECK(static_cast<bool>(blocked[i]) == kOcclusion[i].second);
  }
}

TEST_CASE("camera rays go through the pixel centres of the scene's camera") {
  clrt::Scene scene;
  scene.width = scene.height = 3;
  scene.camera.fov_degrees = 90;  // focal length 3 / (2 tan 45) = 1.5 pixels
  const clrt::compare::RaySet set = clrt::compare::camera_rays(scene);
  REQUIRE(set.rays.size() == 9);
  // Pixel (0, 0): one pixel left of and above the centre, 1.5 ahead along -z.
  const double n = std::sqrt(1 + 1 + 2.25);
  CHECK(set.rays[0].dir[0] == Approx(-1 / n));
  CHECK(set.rays[0].dir[1] == Approx(1 / n));
  CHECK(set.rays[0].dir[2] == Approx(-1.5 / n));
  CHECK(set.rays[4].dir[2] == Approx(-1));
  CHECK(set.rays[4].origin[2] == 5);
}

TEST_CASE("random rays start inside the box, are unit, and cover all directions") {
  const clrt::compare::Bounds box{{-1, 2, 3}, {1, 4, 7}};
  const clrt::compare::RaySet set = clrt::compare::random_rays(box, 20000, 7);
  Vec3 mean;
  for (const HostRay& r : set.rays) {
    for (int k = 0; k < 3; ++k) {
      CHECK(r.origin[k] >= box.lo[k]);
      CHECK(r.origin[k] <= box.hi[k]);
    }
    const Vec3 d{r.dir[0], r.dir[1], r.dir[2]};
    CHECK(length(d) == Approx(1).epsilon(1e-6));
    mean = mean + d / 20000.0;
  }
  // Uniform directions average to 0 (each component has standard error 1 / sqrt(3 * 20000)).
  CHECK(length(mean) < 0.02);
  CHECK(clrt::compare::random_rays(box, 3, 7).rays[2].dir[0] == set.rays[2].dir[0]);
}

TEST_CASE("shadow rays leave the hit point on the ray's side towards the first light") {
  clrt::Scene scene;
  clrt::LightSpec ambient, point;
  ambient.kind = "ambient";
  point.position = {0, 3, 2};
  scene.lights = {ambient, point};
  clrt::compare::RaySet rays{"hand", {ray({0, 0, 0}, {0, 0, 1}), ray({0, 0, 0}, {0, 1, 0})}};
  std::vector<clrt::dev::Hit> hits(2);
  hits[0].geometric_normal = {0, 0, 1, 2};  // t = 2, normal facing away from the ray
  hits[0].instance = 0;
  hits[1].instance = CLRT_NO_HIT;
  const clrt::compare::RaySet shadows = clrt::compare::shadow_rays(scene, rays, hits);
  REQUIRE(shadows.rays.size() == 1);
  const HostRay& s = shadows.rays[0];
  // From (0, 0, 2 - 1e-4) to (0, 3, 2).
  CHECK(s.origin[2] == Approx(2 - 1e-4).epsilon(1e-7));
  CHECK(s.tmax == Approx(std::hypot(3.0, 1e-4)));
  CHECK(s.dir[1] == Approx(1).epsilon(1e-6));
}

TEST_CASE("agreement: t within 1e-3 relative, or near the origin's rounding") {
  clrt::compare::RaySet set{
      "hand",
      {ray({0, 0, 0}, {0, 0, 1}), ray({0, 0, 0}, {0, 0, 1}), ray({0, 0, 0}, {0, 0, 1}),
       ray({0, 0, 0}, {0, 0, 1}), ray({1000, 0, 0}, {0, 0, 1})}};
  std::vector<clrt::dev::Hit> hits(5);
  const float clrt_t[5] = {1.0f, 1.0f, 0.0f, 1.0f, 0.001f};
  for (int i = 0; i < 5; ++i) {
    hits[i].geometric_normal.w = clrt_t[i];
    hits[i].instance = 0;
  }
  hits[2].instance = CLRT_NO_HIT;
  // Agree, disagree (2e-3), both miss, clrt hit but Embree miss, 1e-4 apart at |o| = 1000.
  const std::vector<float> embree_t = {1.0005f, 1.002f, INFINITY, INFINITY, 0.0011f};
  const clrt::compare::Agreement a = clrt::compare::closest_agreement(set, hits, embree_t);
  CHECK(a.share == Approx(3.0 / 5));
  CHECK(a.examples == std::vector<std::size_t>{1, 3});
  CHECK(clrt::compare::occlusion_agreement({1, 0, 1, 0}, {1, 1, 1, 0}).share == Approx(0.75));
}

TEST_CASE("the Whitted tracer on Embree renders the scenes clrt renders, to within rounding") {
  // Spheres, a plane and a mirror; a mesh with vertex normals under a transform; spot lights;
  // loose triangles. Rays that graze an edge may go either way in one tracer and not the other,
  // so a few pixels may differ; the rest agree to float rounding.
  for (const char* name : {"reflect.ray", "mesh.ray", "lights-spot.ray", "triangles.ray"}) {
    INFO(name);
    const clrt::Scene scene = clrt::load_scene(std::string(CLRT_SOURCE_DIR) + "/scenes/" + name);
    REQUIRE(clrt::compare::unsupported_shapes(scene).empty());
    REQUIRE(clrt::compare::unsupported_lights(scene).empty());
    clrt::RenderSetup setup;
    setup.options = clrt::RenderOptions::from_scene(scene);
    setup.options.width = 64;
    setup.options.height = 48;
    setup.options.samples = 1;
    setup.devices = clrt::select_devices("cpu");
    clrt::RenderStats stats;
    const clrt::FloatImage ours = clrt::render(scene, setup, stats);
    const clrt::compare::EmbreeScene embree(scene, 2, RTC_BUILD_QUALITY_HIGH, RTC_SCENE_FLAG_NONE);
    const clrt::FloatImage theirs = clrt::compare::render_whitted(scene, embree, setup.options, 2);
    REQUIRE(theirs.rgb.size() == ours.rgb.size());
    std::size_t apart = 0, lit = 0;
    for (std::size_t k = 0; k < ours.rgb.size(); ++k) {
      apart += std::abs(ours.rgb[k] - theirs.rgb[k]) > 1e-3f;
      lit += ours.rgb[k] > 0.01f;
    }
    CHECK(apart <= ours.rgb.size() / 100);
    CHECK(lit > ours.rgb.size() / 4);  // not two black images
  }
}

TEST_CASE("the Whitted tracer names the lights it cannot render") {
  clrt::Scene scene;
  clrt::LightSpec area;
  area.kind = "area";
  scene.lights = {area, area};
  CHECK(clrt::compare::unsupported_lights(scene) == "2 area lights");
  scene.lights.resize(1);
  CHECK(clrt::compare::unsupported_lights(scene) == "1 area light");
  scene.lights[0].kind = "spot";
  CHECK(clrt::compare::unsupported_lights(scene).empty());
}
