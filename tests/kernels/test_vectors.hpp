// Host-side conversions and comparisons the kernel tests share: device f4 <-> double Vec3, and
// tolerant vector comparison for float results checked against double references.
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "math/vec3.hpp"
#include "shared/common.h"

namespace clrt::test {

inline dev::f4 f4_of(const Vec3& v, double w = 0) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z),
          static_cast<float>(w)};
}

inline Vec3 vec_of(const dev::f4& v) { return {v.x, v.y, v.z}; }
// A Ray's float triples (origin, dir, weight).
inline Vec3 vec_of(const float (&v)[3]) { return {v[0], v[1], v[2]}; }
inline void set_triple(float (&out)[3], const Vec3& v) {
  out[0] = static_cast<float>(v.x);
  out[1] = static_cast<float>(v.y);
  out[2] = static_cast<float>(v.z);
}

inline std::string text_of(const Vec3& v) {
  std::ostringstream out;
  out.precision(9);
  out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return out.str();
}

// |a - b| <= tolerance per component: float results against double references.
inline bool near(const Vec3& a, const Vec3& b, double tolerance) {
  return std::fabs(a.x - b.x) <= tolerance && std::fabs(a.y - b.y) <= tolerance &&
         std::fabs(a.z - b.z) <= tolerance;
}

// A macro so that Catch reports the caller's line.
#define CHECK_NEAR_VEC(actual, expected, tolerance)                                          \
  do {                                                                                       \
    const ::clrt::Vec3 a_ = (actual), e_ = (expected);                                       \
    INFO("actual " << ::clrt::test::text_of(a_) << " expected " << ::clrt::test::text_of(e_)); \
    CHECK(::clrt::test::near(a_, e_, (tolerance)));                                          \
  } while (0)

inline bool same_bits(float a, float b) {
  std::uint32_t x, y;
  static_assert(sizeof x == sizeof a);
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

inline bool same_bits(const dev::f4& a, const dev::f4& b) {
  return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z) && same_bits(a.w, b.w);
}

inline bool same_bits(const float (&a)[3], const float (&b)[3]) {
  return same_bits(a[0], b[0]) && same_bits(a[1], b[1]) && same_bits(a[2], b[2]);
}

}  // namespace clrt::test
