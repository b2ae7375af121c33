/* What every light kind's device file (lights/) returns: one sample of the light as seen
 * from a shading point, and where a ray crosses the light. */
#ifndef CLRT_RENDER_LIGHT_SAMPLE_H
#define CLRT_RENDER_LIGHT_SAMPLE_H

#include "common.h"
#include "random.h"

typedef struct LightSample {
  float3 position;  /* the sampled point (unused for directional lights) */
  float3 to_light;  /* unit direction from the shading point towards the light */
  float distance;   /* INFINITY for directional lights */
  float3 intensity; /* colour reaching the point, before N.L; zero outside a spot's cone */
  /* Path mode's physical reading (docs/path-tracing.md): `geometry` turns the intensity into
   * the irradiance it brings (1 / d^2 for point and spot lights, 1 for directional ones,
   * cos at the light times its area / d^2 for an area light's sample), and `density` is the
   * solid-angle density of the sample for multiple importance sampling (0 for the lights no
   * path can hit). The Whitted terms use neither. */
  float geometry;
  float density;
} LightSample;

/* Where a ray meets a light that paths can hit: the distance t along it (INFINITY: it does not),
 * the radiance it sees there, and the solid-angle density with which one of the light's
 * samples would have chosen that direction, for multiple importance sampling. */
typedef struct LightCrossing {
  float t;
  float3 radiance;
  float density;
} LightCrossing;

CLRT_INLINE LightCrossing no_crossing(void) {
  LightCrossing c;
  c.t = INFINITY;
  c.radiance = (float3)(0.0f);
  c.density = 0.0f;
  return c;
}

/* A sample at `position` of a light that sends `intensity`, seen from p: the inverse-square
 * geometry of a point, and no density (no path can hit a point). */
CLRT_INLINE LightSample sample_at_point(float3 position, float3 intensity, float3 p) {
  LightSample s;
  s.position = position;
  s.intensity = intensity;
  const float3 delta = s.position - p;
  s.distance = length3(delta);
  s.to_light = delta / s.distance;
  const float d2 = s.distance * s.distance;
  s.geometry = 1.0f / d2;
  s.density = 0.0f;
  return s;
}

#endif
