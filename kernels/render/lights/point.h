/* `light r g b point x y z`: all its intensity from one point, falling off with the square of
 * the distance in path mode. */
#ifndef CLRT_RENDER_LIGHTS_POINT_H
#define CLRT_RENDER_LIGHTS_POINT_H

#include "../light_sample.h"

CLRT_INLINE LightSample point_light_sample(__global const Light* light, uint j, float3 p, float2 u) {
  return sample_at_point(xyz(light->position), xyz(light->color), p);
}

CLRT_INLINE bool point_light_reads_pair(void) { return false; }

CLRT_INLINE LightCrossing point_light_crossing(__global const Light* light, float3 o, float3 d,
                                               float tmin, float tmax) {
  return no_crossing();
}

#endif
