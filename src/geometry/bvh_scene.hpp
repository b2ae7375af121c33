// The scene's two-level BVH: one bottom level per mesh, shared by the instances that place it,
// and a top level over every instance except the planes.
#pragma once

#include <vector>

#include "geometry/geometry_data.hpp"
#include "geometry/mesh_table.hpp"

namespace clrt {

// Builds the BVH of `out`, whose instance and mesh tables are filled (mesh m's triangles read
// from sources[m]), whose per-triangle tables are sized and whose nodes are empty: reorders the
// non-plane instances into leaf order, writes each mesh's per-triangle rows in its leaf order,
// fills `nodes`, every Mesh.root_node and `build_seconds`.
void build_scene_bvh(const Scene& scene, const std::vector<TriangleSource>& sources, GeometryData& out);

}  // namespace clrt
