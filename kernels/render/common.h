/* Helpers every stage uses. FP_CONTRACT is off so that no compiler fuses a*b+c differently in
 * different kernels or devices: the same sum must give the same bits wherever it is computed
 * (cast and trace mode agree where no shadow or secondary ray acts). */
#ifndef CLRT_RENDER_COMMON_H
#define CLRT_RENDER_COMMON_H

#pragma OPENCL FP_CONTRACT OFF

#include "../shared/ray.h"
#include "../shared/scene.h"

inline float3 xyz(f4 v) { return v.xyz; }
inline f4 as_f4(float3 v) { return (f4)(v, 0.0f); }

/* x^y for x >= 0, with 0^0 = 1 as pow() has it. exp2(y log2 x) because PoCL's pow() made the
 * whole shade kernel 3.5x slower (250 ms against 72 ms on reflect.ray at 1280x720); the
 * difference is far below what 8-bit output can show. */
inline float power(float x, float y) {
  if (x > 0.0f) return exp2(y * log2(x));
  return y == 0.0f ? 1.0f : 0.0f;
}

#endif
