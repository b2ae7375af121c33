/* `environment FILE [SCALE]`: an equirectangular image of the radiance arriving from every
 * direction, in the orientation of Mitsuba 3's `envmap` emitter: the map's direction
 * d = (x, y, z) falls on u = atan2(x, -z) / (2 pi) (wrapped into [0, 1)) across the image and
 * v = theta / pi = acos(y) / pi down it, +y up at the top row; the current transform's rotation
 * at the command turns the map (world_to_map's rows are position, direction and edge_u). A
 * direction takes the texel it falls in, whose radiance is constant over it.
 *
 * Every mode's escaping rays see it (shade_point.h's miss_colour). Path mode also samples it:
 * a texel in proportion to its luminance times sin(theta) at its row's centre (its solid angle),
 * by the rows' cumulative shares, then the texel's row's, both binary searches; then a point
 * uniform in the texel's (u, v). The density in solid angle is p(u, v) / (2 pi^2 sin(theta)),
 * p(u, v) the texel's share times the texel count; an escaping path claims the same for its
 * direction, from the same tables. The texels follow the record (`data`), as rgb radiance
 * times the scale with, in w, the row's cumulative share through the texel; then the rows'
 * cumulative shares, one float each. */
#ifndef CLRT_RENDER_LIGHTS_ENVIRONMENT_H
#define CLRT_RENDER_LIGHTS_ENVIRONMENT_H

#include "../light_sample.h"
#include "math/cumulative_pick.h"
#include "math/exact.h"

CLRT_INLINE __global const f4* environment_texels(__global const Light* light) {
  return (__global const f4*)light + light->data;
}

/* The rows' cumulative shares of the sampling weight. */
CLRT_INLINE __global const float* environment_rows(__global const Light* light) {
  return (__global const float*)(environment_texels(light) + light->grid_u * light->grid_v);
}

/* The direction in the map's frame. */
CLRT_INLINE float3 environment_to_map(__global const Light* light, float3 d) {
  return (float3)(dot3(xyz(light->position), d), dot3(xyz(light->direction), d), dot3(xyz(light->edge_u), d));
}

/* Where a unit world direction falls: its texel (column, row) and sin(theta) in the map. */
typedef struct EnvironmentPlace {
  uint2 texel;
  float sin_theta;
} EnvironmentPlace;

CLRT_INLINE EnvironmentPlace environment_place(__global const Light* light, float3 d) {
  const float3 m = environment_to_map(light, d);
  const float sin_theta = sqrt(m.x * m.x + m.z * m.z);
  const float turns = exact_atan2(m.x, -m.z) * 0.159154937f;
  const float u = turns < 0.0f ? turns + 1.0f : turns;
  const float v = exact_atan2(sin_theta, m.y) * 0.318309873f;
  const uint w = light->grid_u, h = light->grid_v;
  EnvironmentPlace p;
  p.texel = (uint2)(min(w - 1u, (uint)(u * (float)w)), min(h - 1u, (uint)(v * (float)h)));
  p.sin_theta = sin_theta;
  return p;
}

CLRT_INLINE float3 environment_place_radiance(__global const Light* light, EnvironmentPlace p) {
  return xyz(environment_texels(light)[p.texel.y * light->grid_u + p.texel.x]);
}

/* The share between cumulative values at i - 1 and i of a table `c`. */
CLRT_INLINE float share_at(__global const float* c, uint i) {
  return c[i] - (i == 0u ? 0.0f : c[i - 1u]);
}

/* The solid-angle density of the samples there: the texel's probability times the texel count
 * over 2 pi^2 sin(theta). */
CLRT_INLINE float environment_place_density(__global const Light* light, EnvironmentPlace p) {
  if (!(p.sin_theta > 0.0f)) return 0.0f;
  __global const f4* row = environment_texels(light) + p.texel.y * light->grid_u;
  const float within = row[p.texel.x].w - (p.texel.x == 0u ? 0.0f : row[p.texel.x - 1u].w);
  const float texels = (float)(light->grid_u * light->grid_v);
  return share_at(environment_rows(light), p.texel.y) * within * texels /
         (19.7392088f * p.sin_theta); /* 2 pi^2 */
}

/* The radiance arriving along -d (d the unit direction a ray travels in). */
CLRT_INLINE float3 environment_radiance(__global const Light* light, float3 d) {
  return environment_place_radiance(light, environment_place(light, d));
}

CLRT_INLINE float environment_density(__global const Light* light, float3 d) {
  return environment_place_density(light, environment_place(light, d));
}

CLRT_INLINE LightSample environment_light_sample(__global const Light* light, uint j, float3 p, float2 u) {
  const uint w = light->grid_u, h = light->grid_v;
  float ux = u.x, uy = u.y;
  const uint row = pick_cumulative(environment_rows(light), h, 1u, &ux);
  __global const f4* texels = environment_texels(light) + row * w;
  const uint column = pick_cumulative((__global const float*)texels + 3, w, 4u, &uy);
  /* theta = pi v is half a turn of v; phi = 2 pi u is u turns. */
  float sin_theta, cos_theta, sin_phi, cos_phi;
  sincos_turns(0.5f * (((float)row + uy) / (float)h), &sin_theta, &cos_theta);
  sincos_turns(((float)column + ux) / (float)w, &sin_phi, &cos_phi);
  const float3 m = (float3)(sin_phi * sin_theta, cos_theta, -cos_phi * sin_theta);
  const float3 d = m.x * xyz(light->position) + m.y * xyz(light->direction) + m.z * xyz(light->edge_u);
  LightSample s;
  s.to_light = d;
  s.position = p + d;
  s.distance = INFINITY;
  /* Radiance and density both from the texel d falls in, as an escaping path takes them, so
   * that the pair stays consistent where rounding puts d across a texel's edge. */
  const EnvironmentPlace place = environment_place(light, d);
  s.intensity = environment_place_radiance(light, place);
  s.density = environment_place_density(light, place);
  s.geometry = s.density > 0.0f ? 1.0f / s.density : 0.0f;
  if (!(s.density > 0.0f)) s.intensity = (float3)(0.0f);
  return s;
}

CLRT_INLINE bool environment_light_reads_pair(void) { return true; }

/* Paths meet it by escaping (miss_colour), never by crossing it. */
CLRT_INLINE LightCrossing environment_light_crossing(__global const Light* light, float3 o, float3 d,
                                                     float tmin, float tmax) {
  return no_crossing();
}

#endif
