// The contract's camera model in double, written from the contract (not from frame_setup):
// the ray through image point (x, y) has the direction f F + (x - w/2) R + (h/2 - y) U with
// f = w / (2 tan(fov/2)) (fov across the width), F the unit view direction, R = F x up (unit)
// and U = R x F; pixel (i, j) spans [i, i+1] x [j, j+1] with row 0 at the top.
#pragma once

#include <cmath>
#include <utility>

#include "math/vec3.hpp"

namespace clrt::test {

struct ContractCamera {
  Vec3 eye, forward, right, up;
  double focal;  // in pixels
  int width, height;

  ContractCamera(const Vec3& eye_, const Vec3& lookat, const Vec3& up_hint, double fov_degrees,
                 int width_, int height_)
      : eye(eye_),
        forward(normalize(lookat - eye_)),
        right(normalize(cross(forward, up_hint))),
        up(cross(right, forward)),
        focal(width_ / (2.0 * std::tan(fov_degrees * M_PI / 360.0))),
        width(width_),
        height(height_) {}

  // Unit direction of the ray through image point (x, y).
  Vec3 direction(double x, double y) const {
    return normalize(forward * focal + right * (x - width / 2.0) + up * (height / 2.0 - y));
  }

  // The image point a direction goes through (the inverse of direction()).
  std::pair<double, double> image_point(const Vec3& d) const {
    const double s = focal / dot(d, forward);
    return {width / 2.0 + s * dot(d, right), height / 2.0 - s * dot(d, up)};
  }
};

}  // namespace clrt::test
