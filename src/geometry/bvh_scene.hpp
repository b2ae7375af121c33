// The scene's two-level BVH: one bottom level per mesh, shared by the instances that place it,
// and a top level over every instance except the planes.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "geometry/geometry_data.hpp"
#include "geometry/mesh_table.hpp"

namespace clrt {

// What a render's build frees as it goes (build_geometry_for_render); a hook may be empty.
struct SceneReleaseHooks {
  // Called once mesh m's per-triangle rows are written (from any thread): from then on the build
  // reads only that mesh's positions and corners.
  std::function<void(std::size_t)> rows_written;
  // Called once the build has read all it needs of Scene::instances, before the top level is
  // built: a scene of millions of spheres holds as many bytes in them as in the instance table.
  std::function<void()> instances_read;
};

// Builds the BVH of `out`, whose instance and mesh tables are filled (mesh m's triangles read
// from sources[m]) and whose per-triangle tables and nodes are empty: reorders the non-plane
// instances into leaf order, sizes the per-triangle tables and writes each mesh's rows in its
// leaf order, fills `nodes`, every Mesh.root_node and `build_seconds`.
void build_scene_bvh(const Scene& scene, const std::vector<TriangleSource>& sources, GeometryData& out,
                     const SceneReleaseHooks& hooks = {});

}  // namespace clrt
