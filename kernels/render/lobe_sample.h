/* What every lobe's device file (lobes/) shares: the record a lobe's sampling fills, and the
 * directions drawn about an axis. Directions are unit vectors leaving the surface point; n is
 * the shading normal, turned towards the viewer. */
#ifndef CLRT_RENDER_LOBE_SAMPLE_H
#define CLRT_RENDER_LOBE_SAMPLE_H

#include "math/around_axis.h"
#include "shade_point.h"

#define CLRT_INV_PI 0.318309873f
#define CLRT_INV_TWO_PI 0.159154937f

/* A direction drawn from one lobe. A smooth lobe only draws `dir`: the mixture weighs it with
 * every smooth lobe's value and density (one-sample multiple importance sampling). A delta lobe
 * (mirror, glass) also states the weight, the ray kind and the refraction's radiance scale. */
typedef struct LobeSample {
  float3 dir;
  bool smooth;
  float3 weight;        /* delta lobes: f cos / pdf, with the lobe's choice */
  uint kind;            /* CLRT_RAY_REFLECTION or CLRT_RAY_REFRACTION */
  float radiance_scale; /* within the weight; 1 unless it refracts */
} LobeSample;

CLRT_INLINE LobeSample smooth_sample(float3 dir) {
  LobeSample s;
  s.dir = dir;
  s.smooth = true;
  s.weight = (float3)(0.0f);
  s.kind = CLRT_RAY_REFLECTION;
  s.radiance_scale = 1.0f;
  return s;
}

CLRT_INLINE LobeSample delta_sample(float3 dir, float weight, uint kind, float radiance_scale) {
  LobeSample s;
  s.dir = dir;
  s.smooth = false;
  s.weight = (float3)(weight);
  s.kind = kind;
  s.radiance_scale = radiance_scale;
  return s;
}

/* Cosine-weighted about n. */
CLRT_INLINE float3 sample_cosine(float3 n, float2 u) {
  const float cos_theta = sqrt(1.0f - u.x);
  return around_axis(n, cos_theta, sqrt(fmax(0.0f, 1.0f - cos_theta * cos_theta)), u.y);
}

#endif
