// Triangle meshes as the device's Mesh, Triangle, TriangleNormals and material tables.
#pragma once

#include <vector>

#include "geometry/geometry_data.hpp"

namespace clrt {

// Appends one device mesh holding `mesh`'s triangles (its BVH root is set later).
void append_mesh(const MeshData& mesh, GeometryData& out);

// Appends one device mesh holding the scene's loose `triangle`s, already in world space, each
// with its own material.
void append_loose_triangles(const std::vector<TriangleSpec>& triangles, GeometryData& out);

}  // namespace clrt
