// Cuts a planar polygon (NFF's p and pp) into triangles.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "math/vec3.hpp"

namespace clrt {

using TriangleCorners = std::array<std::size_t, 3>;  // indices into the polygon's vertices

// Triangles that cover the polygon, each counter-clockwise the way the polygon runs (so they
// face the same side). A convex polygon is cut into a fan from its first vertex; a concave one
// (the SPD gears' toothed faces) by ear clipping, which always cuts the first ear in the
// polygon's order. Triangles of zero area are left out, so a degenerate polygon gives none.
std::vector<TriangleCorners> triangulate_polygon(const std::vector<Vec3>& vertices);

}  // namespace clrt
