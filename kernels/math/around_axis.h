/* Directions about an axis, for the lobes' and the lights' samples. */
#ifndef CLRT_MATH_AROUND_AXIS_H
#define CLRT_MATH_AROUND_AXIS_H

#include "exact.h"

/* A unit vector at polar angle theta (given as its cosine and sine) and azimuth 2 pi u about
 * the unit axis a, built in a branch-free orthonormal basis (Duff et al., JCGT 2017). */
CLRT_INLINE float3 around_axis(float3 a, float cos_theta, float sin_theta, float u) {
  const float sign = a.z >= 0.0f ? 1.0f : -1.0f;
  const float k = -1.0f / (sign + a.z);
  const float b = a.x * a.y * k;
  const float3 t = (float3)(1.0f + sign * a.x * a.x * k, sign * b, -sign * a.x);
  const float3 bt = (float3)(b, sign + a.y * a.y * k, -a.y);
  float s, c;
  sincos_turns(u, &s, &c);
  return normalize3((sin_theta * c) * t + (sin_theta * s) * bt + cos_theta * a);
}

#endif
