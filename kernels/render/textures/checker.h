/* The checkerboard: unit squares of (s, t), color0 where floor(s) + floor(t) is even, color1
 * elsewhere, averaged over a square footprint in closed form. As a sign, the pattern is the
 * product of two square waves, +1 on even and -1 on odd unit intervals, so its average over a
 * square is the product of each wave's average over a side, and a wave's average is a
 * difference of its integral, a triangle wave. */
#ifndef CLRT_RENDER_TEXTURES_CHECKER_H
#define CLRT_RENDER_TEXTURES_CHECKER_H

#include "shared/texture.h"

/* The integral of the square wave from 0 to x, for x in [-2, 4]: 1 - |(x mod 2) - 1|. */
CLRT_INLINE float square_wave_integral(float x) {
  const float m = x - 2.0f * floor(0.5f * x);
  return 1.0f - fabs(m - 1.0f);
}

/* The square wave's mean over [x - width / 2, x + width / 2]; its value at x for a footprint
 * below 2^-16 of a square, where the difference would be rounding. */
CLRT_INLINE float square_wave_mean(float x, float width) {
  const float m = x - 2.0f * floor(0.5f * x); /* the wave repeats every 2 */
  if (!(width >= 1.52587891e-05f)) return m < 1.0f ? 1.0f : -1.0f;
  if (width >= 1048576.0f) return 0.0f; /* what is left of whole periods would be rounding */
  if (width >= 2.0f) {
    /* Whole periods average 0; what is left is less than one. */
    const float periods = 2.0f * floor(0.5f * width);
    width -= periods;
    if (width == 0.0f) return 0.0f;
    return (square_wave_integral(m + 0.5f * width) - square_wave_integral(m - 0.5f * width)) /
           (width + periods);
  }
  return (square_wave_integral(m + 0.5f * width) - square_wave_integral(m - 0.5f * width)) / width;
}

CLRT_INLINE float3 checker_value(__global const Texture* tex, float s, float t, float width) {
  if (!(fabs(s) < 1.15292150e18f) || !(fabs(t) < 1.15292150e18f)) s = t = 0.0f;
  const float sign = square_wave_mean(s, width) * square_wave_mean(t, width);
  return (0.5f + 0.5f * sign) * tex->color0.xyz + (0.5f - 0.5f * sign) * tex->color1.xyz;
}

#endif
