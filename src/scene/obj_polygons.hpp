// Cutting an OBJ face of more than three corners into triangles along its shape, once every
// position it names is known.
#pragma once

#include <cstddef>

#include "scene/scene.hpp"

namespace clrt {

// The polygon whose corners `mesh` holds as the fan (0, k, k + 1) in the triangle corners from
// `first_corner` on is cut again, into as many triangles, keeping its winding (and each corner's
// normal and texture coordinate):
// - a quad along its shorter diagonal, from corner 0 to 2 only when that one is strictly shorter
//   (in single precision), as tinyobjloader, which clrt used before, cut it;
// - a larger polygon by ear clipping in the plane of its (Newell) normal, so that a concave
//   polygon is covered exactly; where no ear is left (a polygon that crosses itself, or lies on a
//   line) the fan's next triangle is kept;
// - a polygon of more than limits::kMaxConcavePolygonCorners corners is left as its fan when it
//   is convex, and refused (false, the mesh unchanged) when it is not.
bool triangulate_polygon(MeshData& mesh, std::size_t first_corner, std::size_t corners);

}  // namespace clrt
