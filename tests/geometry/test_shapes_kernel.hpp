// Runs the geometry headers on the device for the shape tests: each ray is mapped into its
// instance's object space, intersected, and its hit mapped back to world space.
#pragma once

#include <vector>

#include "math/mat4.hpp"
#include "math/vec3.hpp"
#include "shape_reference.hpp"
#include "shared/scene.h"

namespace clrt::test {

// v with each component rounded to float: rays the host and the device see alike.
Vec3 round_to_float(const Vec3& v);

// The instance the renderer would build for `shape` (rows of M^-1 and of (M^-1)^T).
dev::Instance make_instance(const PlacedShape& shape);

// A device result, in float as the device computed it.
struct DeviceHit {
  bool hit = false;
  float t = 0;       // on a miss: the ray's tmax, which the intersector must leave alone
  Vec3 normal;       // on a hit: world, unit; on a miss: the untouched kNormalSentinel
  float u = 0, v = 0;  // triangles: weights of v1 and v2 (on a miss, the untouched -7)
};

// What the kernels put in the normal before intersecting, to see that a miss leaves it alone.
const Vec3 kNormalSentinel{7, 8, 9};

// Ray i against shapes[i] through intersect_canonical.
std::vector<DeviceHit> cast_canonical(const std::vector<PlacedShape>& shapes,
                                      const std::vector<WorldRay>& rays);

// Ray i against triangles [i * stride, i * stride + count) of `triangles` (3 object-space
// vertices each), placed by transforms[i], through intersect_triangle; the closest one wins.
std::vector<DeviceHit> cast_triangles(const std::vector<Vec3>& triangles, int count, int stride,
                                      const std::vector<Mat4>& transforms,
                                      const std::vector<WorldRay>& rays);

// Asserts a device hit at `t` whose world normal is `normal` (normalised here), to 1e-5.
void check_hit(const DeviceHit& got, double t, const Vec3& normal);

// Asserts a miss that left t (the ray's tmax) and the normal alone.
void check_miss(const DeviceHit& got, const WorldRay& ray);

// Ray i against shapes[i] on the host and on the device, compared for hit or miss, t and
// normal. Rays whose hit or miss changes when the object is shrunk or grown by a relative
// 1e-3 are too close to a silhouette, rim or the ray's ends to be compared and are skipped;
// the number compared is returned.
int compare_with_reference(const std::vector<PlacedShape>& shapes,
                           const std::vector<WorldRay>& rays);

}  // namespace clrt::test
