// The scene's two-level BVH: one bottom level per mesh, shared by the instances that place it,
// and a top level over every instance except the planes.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "geometry/geometry_data.hpp"
#include "geometry/mesh_table.hpp"

namespace clrt {

// Builds the BVH of `out`, whose instance and mesh tables are filled (mesh m's triangles read
// from sources[m]) and whose per-triangle tables and nodes are empty: reorders the non-plane
// instances into leaf order, sizes the per-triangle tables and writes each mesh's rows in its
// leaf order, fills `nodes`, every Mesh.root_node and `build_seconds`. `rows_written(m)`, if given, is called
// once mesh m's per-triangle rows are written (from any thread): from then on the build reads
// only that mesh's positions and corners.
void build_scene_bvh(const Scene& scene, const std::vector<TriangleSource>& sources, GeometryData& out,
                     const std::function<void(std::size_t)>& rows_written = {});

}  // namespace clrt
