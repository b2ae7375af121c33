/* The Whitted local terms of the contract, for one light sample. */
#ifndef CLRT_RENDER_WHITTED_H
#define CLRT_RENDER_WHITTED_H

#include "common.h"

/* kd * Ld * C * (N.L) + ks * Ld * max(0, R.V)^n, where R is L mirrored about N; zero when
 * N.L <= 0. 0^0 is 1 as the contract asks. R.V is held to at most 1, where rounding can leave
 * it: a little above 1 a large exponent (the reader accepts up to 1e12) overflows. */
CLRT_INLINE float3 direct_term(__global const Material* m, float3 n, float3 v, float3 l, float3 ld) {
  const float nl = dot3(n, l);
  if (nl <= 0.0f) return (float3)(0.0f);
  const float3 r = 2.0f * nl * n - l;
  const float highlight = m->ks == 0.0f ? 0.0f : power(clamp(dot3(r, v), 0.0f, 1.0f), m->shininess);
  return m->kd * ld * xyz(m->color) * nl + m->ks * ld * highlight;
}

/* The share of the local colour: 1 - kr - kt, clamped to >= 0. */
CLRT_INLINE float local_share(__global const Material* m) { return fmax(0.0f, 1.0f - m->kr - m->kt); }

#endif
