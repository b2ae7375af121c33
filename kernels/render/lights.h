/* One sample of one light as seen from a shading point. */
#ifndef CLRT_RENDER_LIGHTS_H
#define CLRT_RENDER_LIGHTS_H

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

/* Sample j of `light` from point p; u is the pair of random numbers that places an area light's
 * sample in its stratum, unused by the other kinds (light_is_sampled). Area lights split their
 * intensity evenly over their stratified samples. The switch names every kind: the host uploads
 * no other (src/render/frame_setup.cpp). */
CLRT_INLINE LightSample sample_light(__global const Light* light, uint j, float3 p, float2 u) {
  LightSample s;
  s.intensity = xyz(light->color);
  s.position = xyz(light->position);
  switch (light->kind) {
    case CLRT_LIGHT_DIRECTIONAL:
      s.to_light = -xyz(light->direction);
      s.distance = INFINITY;
      s.position = p + s.to_light;
      s.geometry = 1.0f;
      s.density = 0.0f;
      return s;
    case CLRT_LIGHT_AREA: {
      const float2 uv = stratified(j, light->grid_u, light->grid_v, u);
      s.position += uv.x * xyz(light->edge_u) + uv.y * xyz(light->edge_v);
      s.intensity /= (float)light->samples;
      break;
    }
    case CLRT_LIGHT_POINT:
    case CLRT_LIGHT_SPOT:
      break;
  }
  const float3 delta = s.position - p;
  s.distance = length3(delta);
  s.to_light = delta / s.distance;
  const float d2 = s.distance * s.distance;
  s.geometry = 1.0f / d2;
  s.density = 0.0f;
  if (light->kind == CLRT_LIGHT_AREA) {
    const float3 normal = cross3(xyz(light->edge_u), xyz(light->edge_v));
    const float area = length3(normal);
    const float cos_light = fabs(dot3(normal, s.to_light)) / area;
    /* One of `samples` uniform points: density d^2 / (cos_light area) in solid angle. */
    s.geometry = cos_light * area / d2;
    s.density = cos_light > 0.0f ? d2 / (cos_light * area) : 0.0f;
  }
  if (light->kind == CLRT_LIGHT_SPOT) {
    /* D runs from the light to P: lit when S.D >= cos(angle), scaled by (S.D)^exp. With a
     * cone wider than 90 degrees S.D may be negative: the factor is then 1 for exp 0 (as
     * pow(x, 0) = 1) and 0 otherwise, where pow() of a negative base is undefined. */
    const float sd = dot3(xyz(light->direction), -s.to_light);
    if (sd >= light->cos_cutoff)
      s.intensity *= power(fmax(sd, 0.0f), light->spot_exponent);
    else
      s.intensity = (float3)(0.0f);
  }
  return s;
}

/* Whether sample_light reads its random numbers for `light`: only area lights do, so the others
 * need not draw them. */
CLRT_INLINE bool light_is_sampled(__global const Light* light) { return light->kind == CLRT_LIGHT_AREA; }

#endif
