// A moving instance's two poses as the device interpolates them (kernels/geometry/motion.h):
// each transform split into a translation, a rotation and a symmetric stretch, M = T R S.
#pragma once

#include <array>

#include "math/mat4.hpp"
#include "shared/scene.h"

namespace clrt {

struct Quaternion {
  double x = 0, y = 0, z = 0, w = 1;
};

struct Pose {
  Vec3 translation;
  Quaternion rotation;           // unit
  std::array<double, 9> stretch;  // S, row-major, symmetric
};

// The polar decomposition of m's linear part, A = R S with R a rotation. A mirroring m
// (negative determinant) gives R = -Q and S = -P for A = Q P with det Q = -1, so S is negative
// definite and still interpolates without passing through flat.
Pose decompose(const Mat4& m);

// The device record of the motion from `start` (time 0) to `end` (time 1), which must have the
// same handedness.
dev::InstanceMotion device_motion(const Mat4& start, const Mat4& end);

// Whether the two poses turn differently, so that the moving object's bounds cannot be those of
// its two poses alone.
bool motion_rotates(const Mat4& start, const Mat4& end);

}  // namespace clrt
