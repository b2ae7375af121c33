/* Image textures: bilinear lookups in a mip level, blended between the two levels a footprint
 * falls between (trilinear filtering). */
#ifndef CLRT_RENDER_TEXTURES_IMAGE_H
#define CLRT_RENDER_TEXTURES_IMAGE_H

#include "math/exact.h"
#include "shared/texture.h"

/* A coordinate in [0, 1] by the texture's wrapping: its fraction (repeat) or clamped; a value
 * that is not finite (or beyond 2^60) is taken as 0. */
CLRT_INLINE float wrap_coordinate(float s, u32 wrap) {
  if (!(fabs(s) < 1.15292150e18f)) return 0.0f;
  return wrap == CLRT_WRAP_CLAMP ? clamp(s, 0.0f, 1.0f) : s - floor(s);
}

/* Texel (x, y) of the level at word `base`, `width` texels wide, linear rgb. */
CLRT_INLINE float3 image_texel(__global const uint* texels, u32 format, u32 base, u32 width, u32 x,
                               u32 y) {
  const u32 i = y * width + x;
  if (format == CLRT_TEXELS_FLOAT) {
    __global const uint* w = texels + base + 3u * i;
    return (float3)(as_float(w[0]), as_float(w[1]), as_float(w[2]));
  }
  const uint code = texels[base + i];
  return (float3)(as_float(texels[code & 0xffu]), as_float(texels[(code >> 8) & 0xffu]),
                  as_float(texels[(code >> 16) & 0xffu]));
}

/* Neighbouring texel columns (or rows) i and i + 1 of a level n texels across, for i in
 * [-1, n - 1], by the wrapping. */
CLRT_INLINE void texel_pair(int i, u32 n, u32 wrap, u32* a, u32* b) {
  const int last = (int)n - 1;
  if (wrap == CLRT_WRAP_CLAMP) {
    *a = (u32)max(i, 0);
    *b = (u32)min(i + 1, last);
  } else {
    *a = (u32)(i < 0 ? last : i);
    *b = (u32)(i + 1 > last ? 0 : i + 1);
  }
}

/* The bilinear value of level `level` at wrapped (s, t) in [0, 1]^2; t = 0 is the bottom row. */
CLRT_INLINE float3 image_bilinear(__global const Texture* tex, __global const uint* texels, u32 level,
                                  float s, float t) {
  const u32 words = tex->texel_format == CLRT_TEXELS_FLOAT ? 3u : 1u;
  u32 base = tex->first_word, w = tex->width, h = tex->height;
  for (u32 k = 0; k < level; ++k) {
    base += w * h * words;
    w = max(w >> 1, 1u);
    h = max(h >> 1, 1u);
  }
  const float x = s * (float)w - 0.5f, y = t * (float)h - 0.5f;
  const float x0 = floor(x), y0 = floor(y);
  const float fx = x - x0, fy = y - y0;
  u32 xa, xb, ya, yb;
  texel_pair((int)x0, w, tex->wrap, &xa, &xb);
  texel_pair((int)y0, h, tex->wrap, &ya, &yb);
  const u32 f = tex->texel_format;
  const float3 bottom = (1.0f - fx) * image_texel(texels, f, base, w, xa, ya) +
                        fx * image_texel(texels, f, base, w, xb, ya);
  const float3 top = (1.0f - fx) * image_texel(texels, f, base, w, xa, yb) +
                     fx * image_texel(texels, f, base, w, xb, yb);
  return (1.0f - fy) * bottom + fy * top;
}

/* The image's value at (s, t) for a footprint `width` units of (s, t) across: level 0 when the
 * footprint is at most a texel (or unknown, 0), else the two levels whose texels are nearest its
 * size, blended by log2 of the size. */
CLRT_INLINE float3 image_value(__global const Texture* tex, __global const uint* texels, float s,
                               float t, float width) {
  s = wrap_coordinate(s, tex->wrap);
  t = wrap_coordinate(t, tex->wrap);
  const float texels_across = width * sqrt((float)tex->width * (float)tex->height);
  const float lod = texels_across > 1.0f ? exact_log2(texels_across) : 0.0f;
  const u32 last = tex->levels - 1u;
  if (!(lod < (float)last)) return image_bilinear(tex, texels, last, s, t);
  const float below = floor(lod);
  const float blend = lod - below;
  const float3 fine = image_bilinear(tex, texels, (u32)below, s, t);
  if (blend == 0.0f) return fine;
  return (1.0f - blend) * fine + blend * image_bilinear(tex, texels, (u32)below + 1u, s, t);
}

#endif
