// What the top level of the scene's BVH is built over and what its leaves become: the
// instances after the planes.
#pragma once

#include <optional>
#include <vector>

#include "geometry/bvh_builder.hpp"
#include "geometry/bvh_layout.hpp"
#include "geometry/geometry_data.hpp"
#include "geometry/instance_bounds.hpp"

namespace clrt {

// The top level's items in instance order, as the build takes them: world boxes; spheres the
// device tests in world space may share leaves, everything else is a leaf of its own.
struct TopItems {
  std::vector<Box> boxes;
  std::vector<bool> alone;
  std::vector<SphereLane> spheres;
};

TopItems top_items(const Scene& scene, const GeometryData& geometry, const std::vector<BvhTree>& mesh_trees);

// Per mesh: the instance that is the only one to place it, when it does so with the identity
// transform (the loose triangles' mesh always); else CLRT_NO_HIT.
std::vector<dev::u32> identity_only_instances(const Scene& scene, const GeometryData& geometry);

// The top level's items as the layout takes them, over `geometry`'s instances already in leaf
// order and their `spheres` in that order (moved in).
TopLevelItems top_level_items(const GeometryData& geometry, std::vector<dev::u32> only,
                              std::vector<SphereLane> spheres);

}  // namespace clrt
