// A closed tube around a (2, 3) torus knot: a smooth, self-occluding test mesh whose
// triangle count can be chosen from a few dozen to millions.
#pragma once

#include <cstdint>
#include <vector>

#include "math/vec3.hpp"

namespace clrt::scenes {

struct TriangleMesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;           // one per position: the tube's exact outward normal
  std::vector<std::uint32_t> corners;  // 3 per triangle, counter-clockwise seen from outside
};

// The tessellation: `along` segments along the knot times `around` segments around the tube,
// two triangles each.
struct KnotGrid {
  int along = 3, around = 3;
  long long triangles() const { return 2LL * along * around; }
};

// The grid nearest to `triangles` with segments about 8 times longer along the knot than around
// the tube (both at least 3).
KnotGrid knot_grid_for(long long triangles);

// The knot lies in the xz plane within |x|, |z| < kKnotHalfWidth and |y| < kKnotHalfHeight.
constexpr double kKnotHalfWidth = 3.2;
constexpr double kKnotHalfHeight = 1.2;

TriangleMesh torus_knot(const KnotGrid& grid);

}  // namespace clrt::scenes
