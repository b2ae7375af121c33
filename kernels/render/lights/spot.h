/* `light r g b spot x y z dx dy dz angle [exp]`: a point light that shines only into a cone
 * about its axis S, scaled by (S.D)^exp. */
#ifndef CLRT_RENDER_LIGHTS_SPOT_H
#define CLRT_RENDER_LIGHTS_SPOT_H

#include "../light_sample.h"

CLRT_INLINE LightSample spot_light_sample(__global const Light* light, uint j, float3 p, float2 u) {
  LightSample s = sample_at_point(xyz(light->position), xyz(light->color), p);
  /* D runs from the light to P: lit when S.D >= cos(angle), scaled by (S.D)^exp. With a cone
   * wider than 90 degrees S.D may be negative: the factor is then 1 for exp 0 (as pow(x, 0) =
   * 1) and 0 otherwise, where pow() of a negative base is undefined. */
  const float sd = dot3(xyz(light->direction), -s.to_light);
  if (sd >= light->cos_cutoff)
    s.intensity *= power(fmax(sd, 0.0f), light->spot_exponent);
  else
    s.intensity = (float3)(0.0f);
  return s;
}

CLRT_INLINE bool spot_light_reads_pair(void) { return false; }

CLRT_INLINE LightCrossing spot_light_crossing(__global const Light* light, float3 o, float3 d,
                                              float tmin, float tmax) {
  return no_crossing();
}

#endif
