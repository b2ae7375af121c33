// Double to single precision without undefined behaviour: C++ leaves the conversion of a value
// beyond the float range undefined (UBSan reports it), where the device wants infinity.
#pragma once

#include <limits>

namespace clrt {

// Values beyond the largest float become infinities of their sign; a NaN stays a NaN.
inline float to_float(double v) {
  constexpr double kMax = std::numeric_limits<float>::max();
  constexpr float kInf = std::numeric_limits<float>::infinity();
  if (v > kMax) return kInf;
  if (v < -kMax) return -kInf;
  return static_cast<float>(v);
}

}  // namespace clrt
