// Procedural scenes for the BVH benchmark (clrt-bench bvh): single meshes of any size and fields of instances.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace clrt::bench {

// A lumpy ball mesh of about `triangles` triangles (no vertex normals), placed once.
Scene mesh_scene(int triangles);

// `count` spheres, cylinders, cones and cubes under random rotations and scales, spread with
// constant density, above a ground plane.
Scene shapes_scene(int count);

// `count` instances of one 1,000-triangle mesh under random transforms.
Scene mesh_instances_scene(int count);

}  // namespace clrt::bench
