/* `light r g b directional dx dy dz`: parallel light travelling along a unit direction, with
 * nothing behind the point to stop it but the scene. */
#ifndef CLRT_RENDER_LIGHTS_DIRECTIONAL_H
#define CLRT_RENDER_LIGHTS_DIRECTIONAL_H

#include "../light_sample.h"

CLRT_INLINE LightSample directional_light_sample(__global const Light* light, uint j, float3 p,
                                                 float2 u) {
  LightSample s;
  s.intensity = xyz(light->color);
  s.to_light = -xyz(light->direction);
  s.distance = INFINITY;
  s.position = p + s.to_light;
  s.geometry = 1.0f;
  s.density = 0.0f;
  return s;
}

CLRT_INLINE bool directional_light_reads_pair(void) { return false; }

CLRT_INLINE LightCrossing directional_light_crossing(__global const Light* light, float3 o,
                                                     float3 d, float tmin, float tmax) {
  return no_crossing();
}

#endif
