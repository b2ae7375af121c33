// A double-precision vector as the f4 the shared device records hold (w = 0): here, where the
// set-up starts filling device records, so that math/ needs no kernel header.
#pragma once

#include "math/vec3.hpp"
#include "shared/common.h"

namespace clrt {

inline dev::f4 f4_of(const Vec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0.0f};
}

}  // namespace clrt
