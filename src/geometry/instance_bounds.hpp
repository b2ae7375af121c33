// World boxes of the canonical shapes under their transforms, for the top level of the BVH.
#pragma once

#include "geometry/bvh_box.hpp"
#include "scene/scene.hpp"

namespace clrt {

// The exact (then padded) world box of a sphere, cube, cylinder or cone instance: much tighter
// than its object box carried by M when M rotates, so fewer rays test the shape in vain.
Box shape_world_box(const InstanceSpec& spec);

}  // namespace clrt
