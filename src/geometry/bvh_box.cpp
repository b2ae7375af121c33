#include "geometry/bvh_box.hpp"

#include <cmath>

namespace clrt {

Box padded_world_box(const Vec3& lo, const Vec3& hi) {
  // The world-to-object matrix the device uses is rounded to float, so the object it hits can sit
  // a few ulps of its size and of its distance from the origin away from where double precision
  // puts it.
  const Vec3 far = max(-lo, hi);
  const double pad = 1e-5 * length(hi - lo) + 1e-6 * std::max({far.x, far.y, far.z});
  Box out;
  for (int a = 0; a < 3; ++a) {
    out.lo[a] = std::nextafter(static_cast<float>(lo[a] - pad), -Box::kInf);
    out.hi[a] = std::nextafter(static_cast<float>(hi[a] + pad), Box::kInf);
  }
  return out;
}

Box transformed_box(const Box& box, const Mat4& m) {
  if (box.empty()) return box;
  const double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi = -lo;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{box.lo[0] + (box.hi[0] - box.lo[0]) * (corner & 1),
                 box.lo[1] + (box.hi[1] - box.lo[1]) * ((corner >> 1) & 1),
                 box.lo[2] + (box.hi[2] - box.lo[2]) * ((corner >> 2) & 1)};
    const Vec3 w = m.transform_point(p);
    lo = min(lo, w);
    hi = max(hi, w);
  }
  return padded_world_box(lo, hi);
}

Box lane_box(const dev::BvhNode& node, int k) {
  Box b;
  b.lo[0] = node.min_x.lane[k];
  b.lo[1] = node.min_y.lane[k];
  b.lo[2] = node.min_z.lane[k];
  b.hi[0] = node.max_x.lane[k];
  b.hi[1] = node.max_y.lane[k];
  b.hi[2] = node.max_z.lane[k];
  return b;
}

}  // namespace clrt
