#include "geometry/bvh_box.hpp"

#include <cmath>

#include "math/to_float.hpp"

namespace clrt {

Box padded_world_box(const Vec3& lo, const Vec3& hi) {
  // The world-to-object matrix the device uses is rounded to float, so the object it hits can sit
  // a few ulps of its size and of its distance from the origin away from where double precision
  // puts it.
  const Vec3 far = max(-lo, hi);
  const double pad = 1e-5 * length(hi - lo) + 1e-6 * std::max({far.x, far.y, far.z});
  Box out;
  for (int a = 0; a < 3; ++a) {
    // Beyond the float range a bound is infinite; one that is not a number (inf - inf where a
    // transform overflowed) is unbounded.
    const double l = lo[a] - pad, h = hi[a] + pad;
    out.lo[a] = std::isnan(l) ? -Box::kInf : std::nextafter(to_float(l), -Box::kInf);
    out.hi[a] = std::isnan(h) ? Box::kInf : std::nextafter(to_float(h), Box::kInf);
  }
  return out;
}

BoxSet::BoxSet(const std::vector<Box>& boxes) {
  for (const Box& b : boxes) {
    if (b.empty()) continue;
    for (int a = 0; a < 3; ++a) {
      centre[a].push_back(0.5 * (double(b.lo[a]) + b.hi[a]));
      half[a].push_back(0.5 * (double(b.hi[a]) - b.lo[a]));
    }
  }
}

Box transformed_box(const BoxSet& boxes, const Mat4& m) {
  const std::size_t n = boxes.centre[0].size();
  if (n == 0) return Box{};
  double lo[3], hi[3];
  for (int r = 0; r < 3; ++r) {
    // A box's centre goes where M puts it; its half-size along world axis r is the sum of its
    // half-sizes scaled by |M_rc|: the reach of its farthest corner, without visiting all eight.
    const double* m_r = m.m[r];
    const double abs_r[3] = {std::fabs(m_r[0]), std::fabs(m_r[1]), std::fabs(m_r[2])};
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (std::size_t i = 0; i < n; ++i) {
      const double c = m_r[0] * boxes.centre[0][i] + m_r[1] * boxes.centre[1][i] + m_r[2] * boxes.centre[2][i];
      const double reach = abs_r[0] * boxes.half[0][i] + abs_r[1] * boxes.half[1][i] + abs_r[2] * boxes.half[2][i];
      low = std::min(low, c - reach);
      high = std::max(high, c + reach);
    }
    lo[r] = low + m_r[3];
    hi[r] = high + m_r[3];
  }
  return padded_world_box({lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]});
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
