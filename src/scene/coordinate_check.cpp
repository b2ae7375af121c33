#include "scene/coordinate_check.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/light_kinds.hpp"
#include "scene/limits.hpp"

namespace clrt {
namespace {

struct Box {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  void add(const Vec3& p) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
  double reach() const {
    double r = 0;
    for (int i = 0; i < 3; ++i) r = std::max({r, std::fabs(lo[i]), std::fabs(hi[i])});
    return r;
  }
};

Box mapped(const Box& box, const Mat4& m) {
  Box out;
  for (int corner = 0; corner < 8; ++corner)
    out.add(m.transform_point({corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y,
                               corner & 4 ? box.hi.z : box.lo.z}));
  return out;
}

// The object-space box of the canonical shape or mesh; a plane's stands for the region around
// its origin.
Box object_box(const InstanceSpec& instance, const std::vector<Box>& mesh_boxes) {
  if (instance.shape == ShapeKind::Mesh) return mesh_boxes[static_cast<std::size_t>(instance.mesh)];
  double r = 1;
  if (instance.shape == ShapeKind::Cone) r = std::max({r, instance.cone_r0, instance.cone_r1});
  Box box;
  box.add({-r, -1, -r});
  box.add({r, 1, r});
  return box;
}

}  // namespace

void check_world_point(const Vec3& p, const SourceLocation& where) {
  for (int i = 0; i < 3; ++i)
    if (!(std::fabs(p[i]) <= limits::kMaxCoordinate))
      throw SceneError(where, "a coordinate reaches " + short_number(p[i]) +
                                  " in world space, beyond the limit of " +
                                  short_number(limits::kMaxCoordinate) +
                                  " (the device computes in single precision)");
}

void check_coordinates(const LoaderState& state) {
  const Scene& scene = state.scene;
  std::vector<Box> mesh_boxes(scene.meshes.size());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m)
    for (const Vec3& p : scene.meshes[m].positions) mesh_boxes[m].add(p);

  Box world;
  world.add(scene.camera.eye);
  for (const TriangleSpec& t : scene.triangles) {
    world.add(t.v0);
    world.add(t.v1);
    world.add(t.v2);
  }
  for (const LightSpec& light : scene.lights)
    if (light_kind(light.kind).placed) world.add(light.position);
  // A moving object is checked at both its poses (between them it turns about, and stretches
  // between, the two).
  const auto for_each_pose = [&](const InstanceSpec& instance, const auto& check) {
    check(instance.transform);
    if (instance.motion >= 0) check(scene.end_transforms[static_cast<std::size_t>(instance.motion)]);
  };
  for (const InstanceSpec& instance : scene.instances)
    for_each_pose(instance, [&](const Mat4& pose) {
      const Box box = mapped(object_box(instance, mesh_boxes), pose);
      if (!(box.reach() <= limits::kMaxCoordinate))
        throw SceneError(instance_location(scene, instance), "this object reaches " + short_number(box.reach()) +
                                             " in world space, beyond the limit of " +
                                             short_number(limits::kMaxCoordinate) +
                                             " (the device computes in single precision)");
      if (instance.shape != ShapeKind::Plane) {
        world.add(box.lo);
        world.add(box.hi);
      }
    });
  for (const InstanceSpec& instance : scene.instances)
    for_each_pose(instance, [&](const Mat4& pose) {
      const double reach = mapped(world, pose.inverse()).reach();
      if (!(reach <= limits::kMaxCoordinate))
        throw SceneError(instance_location(scene, instance),
                         "this object is so small for the scene around it that, in its own "
                         "coordinates (where the device intersects it), the scene reaches " +
                             short_number(reach) + ", beyond the limit of " +
                             short_number(limits::kMaxCoordinate));
    });
}

}  // namespace clrt
