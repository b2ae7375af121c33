// An independent host computation of ray hits with placed canonical objects and triangles, in
// double precision and in WORLD space: the kernels intersect the canonical object with the ray
// mapped to object space as the meet of convex pieces; this reference enumerates the world-space
// surface patches (quadrics transformed by M^-1, planar faces and discs spanned by M's images of
// the object's axes) and keeps the nearest hit.
#pragma once

#include <limits>

#include "math/mat4.hpp"
#include "math/vec3.hpp"
#include "shared/scene.h"

namespace clrt::test {

struct PlacedShape {
  dev::u32 shape = CLRT_SHAPE_SPHERE;  // CLRT_SHAPE_* except MESH
  double cone_r0 = 1, cone_r1 = 0;
  Mat4 transform;  // M: object to world
};

struct WorldRay {
  Vec3 origin, dir;  // dir need not be unit: t is measured in units of dir
  double tmin = 1e-4;
  double tmax = std::numeric_limits<double>::infinity();
};

struct ReferenceHit {
  bool hit = false;
  double t = 0;
  Vec3 normal;  // world space, unit, outward (not flipped towards the ray)
  // How far (in object units) the hit point lies from the edge of the surface patch it is on
  // (a cube face's edges, a cylinder's rim): near an edge either neighbouring normal is right.
  double edge_distance = std::numeric_limits<double>::infinity();
  double u = 0, v = 0;  // triangles: weights of v1 and v2
};

ReferenceHit reference_intersect(const PlacedShape& shape, const WorldRay& ray);

// The triangle v0 v1 v2 (object space) placed by M; its normal is the geometric normal carried
// as the contract says, by (M^-1)^T: the world cross product, reversed when M mirrors.
ReferenceHit reference_triangle(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Mat4& m,
                                const WorldRay& ray);

}  // namespace clrt::test
