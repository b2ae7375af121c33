// Cuts a planar polygon (NFF's p and pp) into triangles.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "math/vec3.hpp"

namespace clrt {

using TriangleCorners = std::array<std::size_t, 3>;  // indices into the polygon's vertices

// Triangles that cover the polygon, each counter-clockwise the way the polygon runs (so they
// face the same side). A convex polygon is cut into a fan from its first vertex; a concave one
// (the SPD gears' toothed faces) by ear clipping, which always cuts the first ear in the
// polygon's order. Triangles of zero area are left out, so a degenerate polygon gives none.
// Throws ConcavePolygonTooLarge for a concave polygon of more than
// limits::kMaxConcavePolygonCorners corners, before any cutting.
std::vector<TriangleCorners> triangulate_polygon(const std::vector<Vec3>& vertices);

// A concave polygon beyond the corner limit; what() says so, without a place in the file.
class ConcavePolygonTooLarge : public std::runtime_error {
 public:
  explicit ConcavePolygonTooLarge(std::size_t corners);
};

}  // namespace clrt
