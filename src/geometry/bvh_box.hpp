// Axis-aligned boxes in single precision, as the device stores them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "math/mat4.hpp"
#include "shared/bvh.h"

namespace clrt {

struct Box {
  float lo[3] = {kInf, kInf, kInf};
  float hi[3] = {-kInf, -kInf, -kInf};

  static constexpr float kInf = std::numeric_limits<float>::infinity();

  bool empty() const { return lo[0] > hi[0]; }

  void grow(float x, float y, float z) {
    const float p[3] = {x, y, z};
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }

  void grow(const Box& b) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], b.lo[a]);
      hi[a] = std::max(hi[a], b.hi[a]);
    }
  }

  float center(int axis) const { return 0.5f * (lo[axis] + hi[axis]); }

  // Half the surface area: the SAH only compares areas, so the factor 2 is left out.
  float half_area() const {
    if (empty()) return 0.0f;
    const float x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
    return x * y + y * z + z * x;
  }
};

// The world box [lo, hi] of an object the device intersects in its object space, rounded
// outwards to float and padded so that a single-precision ray-box test in world space does not
// miss what the object-space test would hit.
Box padded_world_box(const Vec3& lo, const Vec3& hi);

// Boxes as their centres and half-sizes, one array per axis: carried by a transform with a few
// vector operations per axis, which matters when one set is carried by each of 100k instances.
struct BoxSet {
  std::vector<double> centre[3], half[3];
  explicit BoxSet(const std::vector<Box>& boxes);  // empty boxes are left out
};

// The padded world box around `boxes` (in object space) after the affine transform `m` (empty
// when there are none).
Box transformed_box(const BoxSet& boxes, const Mat4& m);

// The box of lane `k` of a device node (empty for an empty lane).
Box lane_box(const dev::BvhNode& node, int k);

}  // namespace clrt
