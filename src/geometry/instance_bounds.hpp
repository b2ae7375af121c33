// World boxes of the canonical shapes under their transforms, for the top level of the BVH.
#pragma once

#include <optional>

#include "geometry/bvh_box.hpp"
#include "scene/scene.hpp"

namespace clrt {

// The exact (then padded) world box of a sphere, cube, cylinder or cone instance: much tighter
// than its object box carried by M when M rotates, so fewer rays test the shape in vain.
Box shape_world_box(const InstanceSpec& spec);

// The padded world box of a sphere, cube, cylinder or cone instance that moves from its
// transform to `end` (geometry/instance_motion.hpp), over the whole motion.
Box moving_shape_box(const InstanceSpec& spec, const Mat4& end);

// The same for a mesh instance whose leaf boxes are `boxes`, moving from `start` to `end`.
Box moving_box(const BoxSet& boxes, const Mat4& start, const Mat4& end);

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
