/* Drawing an index in proportion to its share, from a table of cumulative shares (the last 1),
 * as the glow light picks a row and the environment a row and a texel. */
#ifndef CLRT_MATH_CUMULATIVE_PICK_H
#define CLRT_MATH_CUMULATIVE_PICK_H

#include "shared/common.h"

/* The first index whose cumulative value exceeds *u, among `count` values `stride` floats
 * apart, with *u rescaled to its place within that index's share, so that one number both
 * picks and then places. */
CLRT_INLINE uint pick_cumulative(__global const float* cumulative, uint count, uint stride, float* u) {
  uint lo = 0u, hi = count - 1u;
  while (lo < hi) {
    const uint mid = (lo + hi) / 2u;
    if (cumulative[mid * stride] > *u) hi = mid;
    else lo = mid + 1u;
  }
  const float before = lo == 0u ? 0.0f : cumulative[(lo - 1u) * stride];
  *u = fmin((*u - before) / (cumulative[lo * stride] - before), 0x1.fffffep-1f);
  return lo;
}

#endif
