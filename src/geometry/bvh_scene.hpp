// The scene's two-level BVH: one bottom level per mesh, shared by the instances that place it,
// and a top level over every instance except the planes.
#pragma once

#include "geometry/geometry_data.hpp"

namespace clrt {

// Builds the BVH of `out`, whose instance, mesh and triangle tables are filled and whose nodes
// are empty: reorders the non-plane instances and each mesh's triangles into leaf order,
// fills `nodes`, every Mesh.root_node and `build_seconds`.
void build_scene_bvh(const Scene& scene, GeometryData& out);

}  // namespace clrt
