/* `light r g b area x y z ux uy uz vx vy vz [samples]`: a parallelogram that emits its colour as
 * radiance from both faces, sampled at `samples` stratified points, each taking an equal share
 * of its intensity; paths that cross it see it.
 *
 * The Whitted modes place the points uniformly on its surface, as the course does. Path mode
 * draws them uniformly in the solid angle a rectangle subtends (math/spherical_rectangle.h),
 * which spares the points beside a light the noise of samples whose 1 / d^2 varies across it,
 * wherever that angle is large enough for single precision to hold it (1/64 sr: beyond, the
 * light looks small and uniform points are nearly as good); a parallelogram that is not a
 * rectangle keeps uniform points. Sampling and crossing decide alike from the same point, so
 * multiple importance sampling weighs each direction with the density that drew it. */
#ifndef CLRT_RENDER_LIGHTS_AREA_H
#define CLRT_RENDER_LIGHTS_AREA_H

#include "../light_sample.h"
#include "math/spherical_rectangle.h"

/* The program's transport model (render/transport_step.h) decides how points are drawn. */
#if defined(CLRT_TRANSPORT) && CLRT_TRANSPORT == CLRT_MODE_PATH
#define CLRT_AREA_BY_SOLID_ANGLE 1
#else
#define CLRT_AREA_BY_SOLID_ANGLE 0
#endif

#define CLRT_AREA_MIN_SOLID_ANGLE 0.015625f

/* Whether `light` is drawn by solid angle from o; if so, *r holds its spherical rectangle. */
CLRT_INLINE bool area_light_by_solid_angle(__global const Light* light, float3 o, SphericalRectangle* r) {
  /* The host worked out the edges' lengths, the unit normal and whether the light is a
   * rectangle (src/scene/light_kinds.cpp): every sample would otherwise repeat them. */
  if (!CLRT_AREA_BY_SOLID_ANGLE || light->direction.w == 0.0f) return false;
  const float lu = light->edge_u.w, lv = light->edge_v.w;
  const float3 c = xyz(light->position), n = xyz(light->direction);
  /* The solid angle is at most the area over the squared distance h to the light's plane: a
   * light that cannot reach the threshold costs no arctangent. */
  const float h = fabs(dot3(c - o, n));
  if (lu * lv < CLRT_AREA_MIN_SOLID_ANGLE * h * h) return false;
  *r = spherical_rectangle(c, xyz(light->edge_u), lu, xyz(light->edge_v), lv, n, o);
  /* A point in the light's plane (z0 = 0) would give infinite tangents and samples at o itself. */
  return r->z0 < 0.0f && r->solid_angle >= CLRT_AREA_MIN_SOLID_ANGLE;
}

/* Sample j of the light's grid_u x grid_v strata, placed in its stratum by u. */
CLRT_INLINE LightSample area_light_sample(__global const Light* light, uint j, float3 p, float2 u) {
  const float2 uv = stratified(j, light->grid_u, light->grid_v, u);
  SphericalRectangle r;
  if (area_light_by_solid_angle(light, p, &r)) {
    LightSample s = sample_at_point(p + spherical_rectangle_point(&r, uv),
                                    xyz(light->color) / (float)light->samples, p);
    /* One of `samples` points uniform in the solid angle S: density 1 / S. */
    s.geometry = r.solid_angle;
    s.density = 1.0f / r.solid_angle;
    return s;
  }
  const float3 position =
      xyz(light->position) + (uv.x * xyz(light->edge_u) + uv.y * xyz(light->edge_v));
  LightSample s = sample_at_point(position, xyz(light->color) / (float)light->samples, p);
  const float d2 = s.distance * s.distance;
  const float3 normal = cross3(xyz(light->edge_u), xyz(light->edge_v));
  const float area = length3(normal);
  const float cos_light = fabs(dot3(normal, s.to_light)) / area;
  /* One of `samples` uniform points: density d^2 / (cos_light area) in solid angle. */
  s.geometry = cos_light * area / d2;
  s.density = cos_light > 0.0f ? d2 / (cos_light * area) : 0.0f;
  return s;
}

CLRT_INLINE bool area_light_reads_pair(void) { return true; }

/* Where o + t d with t in (tmin, tmax) crosses the parallelogram, and the density with which one
 * uniform sample of it would have been drawn in that direction. */
CLRT_INLINE LightCrossing area_light_crossing(__global const Light* light, float3 o, float3 d,
                                              float tmin, float tmax) {
  const float3 u = xyz(light->edge_u), v = xyz(light->edge_v);
  const float3 normal = cross3(u, v); /* its length is the area */
  const float facing = dot3(normal, d);
  if (facing == 0.0f) return no_crossing();
  const float t = dot3(normal, xyz(light->position) - o) / facing;
  if (!(t > tmin && t < tmax)) return no_crossing();
  const float3 p = o + t * d - xyz(light->position);
  const float n2 = dot3(normal, normal);
  const float a = dot3(cross3(p, v), normal) / n2, b = dot3(cross3(u, p), normal) / n2;
  if (!(a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f)) return no_crossing();
  const float area = sqrt(n2);
  const float cos_light = fabs(facing) / area;
  LightCrossing c;
  c.t = t;
  c.radiance = xyz(light->color);
  SphericalRectangle r;
  c.density = area_light_by_solid_angle(light, o, &r) ? 1.0f / r.solid_angle : t * t / (cos_light * area);
  return c;
}

#endif
