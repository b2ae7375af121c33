/* Noise: Perlin's gradient noise on the integer lattice of (s, t), summed over octaves of twice
 * the frequency and half the amplitude (fractional Brownian motion), mapped from color0 (at -1)
 * to color1 (at +1). An octave whose lattice is finer than the footprint adds its mean, 0,
 * instead of aliasing: it fades out while the footprint grows from a quarter to a half of its
 * cell. */
#ifndef CLRT_RENDER_TEXTURES_NOISE_H
#define CLRT_RENDER_TEXTURES_NOISE_H

#include "render/random.h"
#include "shared/texture.h"

/* The lattice point (i, j)'s gradient, one of eight unit directions, dotted with (x, y). */
CLRT_INLINE float lattice_gradient(int i, int j, float x, float y) {
  const uint h = hash_combine(hash_u32((uint)i), (uint)j) >> 29;
  const float a = (h & 1u) ? 0.707106769f : 1.0f;
  const float b = (h & 1u) ? 0.707106769f : 0.0f;
  /* h / 2 picks the quadrant of the direction (a, b) turned by h / 2 quarter turns. */
  const uint q = h >> 1;
  const float gx = q == 0u ? a : q == 1u ? -b : q == 2u ? -a : b;
  const float gy = q == 0u ? b : q == 1u ? a : q == 2u ? -b : -a;
  return gx * x + gy * y;
}

CLRT_INLINE float noise_fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

/* One octave at (s, t), in about [-1, 1] (the gradients' largest sum, sqrt(2) / 2, scaled to 1);
 * the lattice repeats every 2^16 cells. */
CLRT_INLINE float gradient_noise(float s, float t) {
  s -= 65536.0f * floor(s * (1.0f / 65536.0f));
  t -= 65536.0f * floor(t * (1.0f / 65536.0f));
  const float fs = floor(s), ft = floor(t);
  const int i = (int)fs, j = (int)ft;
  const float x = s - fs, y = t - ft;
  const int i1 = (i + 1) & 0xffff, j1 = (j + 1) & 0xffff;
  const float n00 = lattice_gradient(i, j, x, y), n10 = lattice_gradient(i1, j, x - 1.0f, y);
  const float n01 = lattice_gradient(i, j1, x, y - 1.0f), n11 = lattice_gradient(i1, j1, x - 1.0f, y - 1.0f);
  const float wx = noise_fade(x), wy = noise_fade(y);
  const float bottom = n00 + wx * (n10 - n00), top = n01 + wx * (n11 - n01);
  return 1.41421354f * (bottom + wy * (top - bottom));
}

CLRT_INLINE float3 noise_value(__global const Texture* tex, float s, float t, float width) {
  if (!(fabs(s) < 1.15292150e18f) || !(fabs(t) < 1.15292150e18f)) s = t = 0.0f;
  float sum = 0.0f, amplitude = 0.5f, frequency = 1.0f;
  for (u32 k = 0; k < tex->octaves; ++k) {
    const float cells = width * frequency; /* the footprint in this octave's cells */
    const float keep = clamp(2.0f - 4.0f * cells, 0.0f, 1.0f);
    if (keep == 0.0f) break;
    sum += keep * amplitude * gradient_noise(s * frequency, t * frequency);
    amplitude *= 0.5f;
    frequency *= 2.0f;
  }
  const float a = clamp(0.5f + sum, 0.0f, 1.0f);
  return (1.0f - a) * tex->color0.xyz + a * tex->color1.xyz;
}

#endif
