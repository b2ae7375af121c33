/* The glow light, path mode's light made of the scene's glowing geometry rather than of a `light`
 * command: the glowing triangles (of meshes, cubes and `triangle`s) and spheres that the host put
 * in its emitter table (src/geometry/emitter_table.cpp), whose rows lie in the light table
 * after the records. One sample per shading point picks a row in proportion to its power, then a point
 * of it: uniformly by area on a triangle, uniformly in the cone of directions a sphere subtends
 * (as pbrt-v4 and Mitsuba 3 sample spheres). Paths that hit the same surfaces meet them as
 * geometry, never as a light crossing: path_step weighs what they find with glow_light_density,
 * the density with which this sample would have drawn that direction. The Whitted modes have
 * no glow light: there, glowing surfaces are seen and light nothing. */
#ifndef CLRT_RENDER_LIGHTS_GLOW_H
#define CLRT_RENDER_LIGHTS_GLOW_H

#include "../light_sample.h"
#include "math/around_axis.h"
#include "math/cumulative_pick.h"

CLRT_INLINE __global const Emitter* glow_rows(__global const Light* light) {
  return (__global const Emitter*)((__global const f4*)light + light->data);
}

/* The weights of luminance (Rec. 709) by which the host shares the samples among the rows. */
CLRT_INLINE float glow_luminance(float3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

/* The probability per unit area that a sample picks a point of a glowing surface of emission e:
 * its power share over its area, whatever row holds it. */
CLRT_INLINE float glow_area_share(__global const Light* light, float3 e) {
  return glow_luminance(e) / light->color.w;
}

/* 1 - cos of the half-angle of the cone that a sphere of radius r subtends at distance dist > r,
 * from the sine's square, without the cancellation of 1 - cos for a small cone. */
CLRT_INLINE float cone_one_minus_cos(float r, float dist) {
  const float s = r / dist;
  const float s2 = s * s;
  return s2 / (1.0f + sqrt(1.0f - s2));
}

/* The solid-angle density of a sphere's sample: its row's share (area_share times 4 pi r^2)
 * over the cone's solid angle 2 pi (1 - cos). */
CLRT_INLINE float glow_sphere_density(float area_share, float r, float dist) {
  return area_share * (2.0f * r * r) / cone_one_minus_cos(r, dist);
}

/* The shadow ray aims a little in front of the sampled point, or the emitter itself, met at the
 * end of the ray within rounding, would hide its own light: by 1e-4 scene units near the origin,
 * proportionally more further out where floats are coarser. */
CLRT_INLINE float3 glow_shadow_target(float3 x, float3 unit_normal) {
  const float scale = fmax(1.0f, fmax(fabs(x.x), fmax(fabs(x.y), fabs(x.z))));
  return x + (1e-4f * scale) * unit_normal;
}

/* A sample that brings nothing: p sees the back of the surface, or is inside a sphere. */
CLRT_INLINE LightSample glow_nothing(float3 p) {
  LightSample s = sample_at_point(p + (float3)(0.0f, 0.0f, 1.0f), (float3)(0.0f), p);
  s.geometry = 0.0f;
  return s;
}

/* The unit normal at a sphere's sampled point, offset from the centre by `outward`, which
 * the direction w from the shading point reached. A sphere smaller than the floats' spacing
 * around the point (a radius of 1e-8 seen from 1 unit away) has its point rounded by more than
 * its radius, and `outward` (zero, or a few radii in any direction) names no side of it: there
 * the side that faces the shading point, -w, stands in. */
CLRT_INLINE float3 glow_sphere_normal(float3 outward, float r, float3 w) {
  const float off = length3(outward);
  return off > 0.5f * r && off < 2.0f * r ? outward / off : -w;
}

CLRT_INLINE LightSample glow_sphere_sample(__global const Light* light, __global const Emitter* e,
                                           float3 p, float2 u) {
  const float3 c = xyz(e->origin);
  const float r = e->edge1.w;
  const float3 to_centre = c - p;
  const float dist = length3(to_centre);
  if (!(dist > r)) return glow_nothing(p);
  const float t = u.x * cone_one_minus_cos(r, dist); /* 1 - cos theta */
  const float cos_theta = 1.0f - t;
  const float sin_theta = sqrt(fmax(0.0f, t * (2.0f - t)));
  const float3 w = around_axis(to_centre / dist, cos_theta, sin_theta, u.y);
  /* The near one of the two points where the direction meets the sphere. */
  const float along = dist * cos_theta - sqrt(fmax(0.0f, r * r - dist * dist * (sin_theta * sin_theta)));
  const float3 x = p + along * w;
  LightSample s = sample_at_point(glow_shadow_target(x, glow_sphere_normal(x - c, r, w)), xyz(e->radiance), p);
  s.density = glow_sphere_density(glow_area_share(light, xyz(e->radiance)), r, dist);
  s.geometry = 1.0f / s.density;
  return s;
}

CLRT_INLINE LightSample glow_triangle_sample(__global const Light* light, __global const Emitter* e,
                                             float3 p, float2 u) {
  const float su = sqrt(u.x);
  const float3 e1 = xyz(e->edge1), e2 = xyz(e->edge2);
  const float3 x = xyz(e->origin) + (su * (1.0f - u.y)) * e1 + (su * u.y) * e2;
  const float3 n = cross3(e1, e2);
  const float3 delta = x - p;
  const float d2 = dot3(delta, delta);
  /* Its cosine at the light times |n| times the distance: positive on the glowing side. */
  const float facing = -dot3(n, delta);
  if (!(facing > 0.0f)) return glow_nothing(p);
  const float n_length = length3(n);
  LightSample s = sample_at_point(glow_shadow_target(x, n / n_length), xyz(e->radiance), p);
  const float cos_light = facing / (n_length * sqrt(d2));
  s.density = glow_area_share(light, xyz(e->radiance)) * d2 / cos_light;
  s.geometry = 1.0f / s.density;
  return s;
}

CLRT_INLINE LightSample glow_light_sample(__global const Light* light, uint j, float3 p, float2 u) {
  __global const Emitter* rows = glow_rows(light);
  float within = u.x;
  /* Rows in proportion to their power: the cumulative shares are the rows' origin.w, 16 floats
   * apart. */
  __global const Emitter* e =
      rows + pick_cumulative((__global const float*)rows + 3, light->grid_u, 16u, &within);
  const float2 v = (float2)(within, u.y);
  return e->edge1.w > 0.0f ? glow_sphere_sample(light, e, p, v) : glow_triangle_sample(light, e, p, v);
}

CLRT_INLINE bool glow_light_reads_pair(void) { return true; }

CLRT_INLINE LightCrossing glow_light_crossing(__global const Light* light, float3 o, float3 d,
                                              float tmin, float tmax) {
  return no_crossing();
}

/* The solid-angle density with which a sample from o would have drawn the glowing point that a
 * ray from o met at distance t, whose surface (Hit.glow: CLRT_GLOW_TRIANGLES or a sphere's row)
 * emits `emission` and turns cos_light = |n.d| to the ray. */
CLRT_INLINE float glow_light_density(__global const Light* light, uint glow, float3 o, float t,
                                     float cos_light, float3 emission) {
  const float share = glow_area_share(light, emission);
  if (glow == CLRT_GLOW_TRIANGLES) return cos_light > 0.0f ? share * (t * t) / cos_light : 0.0f;
  __global const Emitter* e = glow_rows(light) + glow;
  const float r = e->edge1.w;
  const float dist = length3(xyz(e->origin) - o);
  return dist > r ? glow_sphere_density(share, r, dist) : 0.0f;
}

#endif
