// World boxes of the canonical shapes under their transforms, for the top level of the BVH.
#pragma once

#include <optional>

#include "geometry/bvh_box.hpp"
#include "scene/scene.hpp"

namespace clrt {

// The exact (then padded) world box of a sphere, cube, cylinder or cone instance: much tighter
// than its object box carried by M when M rotates, so fewer rays test the shape in vain.
Box shape_world_box(const InstanceSpec& spec);

// A sphere in world space.
struct WorldSphere {
  Vec3 center;
  double radius = 0;
};

// The world sphere of a sphere instance whose transform is a similarity (rotation, uniform
// scale, translation, to a relative 1e-6), which the device can then test without mapping the
// ray into object space; nothing for any other instance.
std::optional<WorldSphere> world_sphere(const InstanceSpec& spec);

}  // namespace clrt
