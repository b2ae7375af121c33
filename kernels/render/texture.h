/* The material at a hit with its textures applied. Each ray carries a cone (Amanatides 1984;
 * Akenine-Moller et al., "Texture Level of Detail Strategies for Real-Time Ray Tracing", 2019):
 * it starts at the camera with the angle a pixel spans and widens by that angle per unit of
 * distance, through reflections and refractions alike (surfaces are taken as flat). Where it
 * lands, its width over the cosine of its angle to the surface, over the world length of a unit
 * of (u, v) there, is the footprint in (u, v) the texture is filtered over: mip levels for
 * images, a closed-form average for the checkerboard, fewer octaves for noise. */
#ifndef CLRT_RENDER_TEXTURE_H
#define CLRT_RENDER_TEXTURE_H

#include "common.h"
#include "shared/ray.h"
#include "shared/scene.h"
#include "textures/checker.h"
#include "textures/image.h"
#include "textures/noise.h"

/* A cone's width as Ray.sample_cone keeps it (CLRT_CONE_CODE), and back. */
CLRT_INLINE uint cone_code(float width) {
  if (!(width > 0.0f)) return 0u;
  return (uint)clamp(rint(256.0f * exact_log2(width)) + 32768.0f, 1.0f, 65535.0f);
}

CLRT_INLINE float cone_width_of(uint code) {
  return code == 0u ? 0.0f : exact_exp2(((float)code - 32768.0f) * (1.0f / 256.0f));
}

/* The width of the ray's cone where it meets its hit. */
CLRT_INLINE float cone_width_at_hit(const Ray* ray, const Hit* hit, float cone_spread) {
  return cone_width_of(CLRT_CONE_CODE(*ray)) + cone_spread * hit->geometric_normal.w;
}

/* The cone's footprint on the hit surface in units of (u, v); 0 where the surface gives no
 * scale (a degenerate mapping), which takes the finest detail. */
CLRT_INLINE float uv_footprint(const Ray* ray, const Hit* hit, float cone_width) {
  if (!(hit->uv_scale > 0.0f)) return 0.0f;
  const float cosine = fabs(dot3(hit->geometric_normal.xyz, vload3(0, ray->dir)));
  const float width = cone_width / (hit->uv_scale * cosine);
  return width >= 0.0f ? width : 0.0f; /* 0 / 0 at a grazing hit next to the camera */
}

/* Texture `tex` at (u, v), filtered over a footprint `width` units of (u, v) across. */
CLRT_INLINE float3 texture_value(__global const Texture* tex, __global const uint* texels, float u,
                                 float v, float width) {
  const float s = u * tex->scale[0] + tex->offset[0];
  const float t = v * tex->scale[1] + tex->offset[1];
  const float st_width = width * sqrt(fabs(tex->scale[0] * tex->scale[1]));
  if (tex->kind == CLRT_TEXTURE_CHECKER) return checker_value(tex, s, t, st_width);
  if (tex->kind == CLRT_TEXTURE_NOISE) return noise_value(tex, s, t, st_width);
  return image_value(tex, texels, s, t, st_width);
}

/* The hit's material with each textured term multiplied by its texture's value there: the colour
 * by the rgb value, ks, kr and kt by the mean of its channels. */
CLRT_INLINE Material surface_material(__global const Material* materials,
                                      __global const Texture* textures, __global const uint* texels,
                                      const Ray* ray, const Hit* hit, float cone_width) {
  Material m = materials[hit->material];
  if ((m.textures[0] | m.textures[1] | m.textures[2] | m.textures[3]) == 0u) return m;
  const float width = uv_footprint(ray, hit, cone_width);
  for (u32 slot = 0; slot < CLRT_TEXTURE_SLOTS; ++slot) {
    if (m.textures[slot] == CLRT_NO_TEXTURE) continue;
    const float3 value = texture_value(textures + m.textures[slot], texels, hit->u, hit->v, width);
    if (slot == CLRT_TEXTURE_SLOT_COLOR) m.color = as_f4(xyz(m.color) * value);
    else if (slot == CLRT_TEXTURE_SLOT_KS) m.ks *= mean3(value);
    else if (slot == CLRT_TEXTURE_SLOT_KR) m.kr *= mean3(value);
    else m.kt *= mean3(value);
  }
  return m;
}

#endif
