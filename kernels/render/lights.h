/* Every light kind through one door: the rows of CLRT_LIGHT_KINDS (kernels/shared/scene.h), each
 * a device file in lights/, all of which light_files.h (written by the build) includes. A switch
 * per question names every kind; the host uploads no other (src/render/frame_setup.cpp). */
#ifndef CLRT_RENDER_LIGHTS_H
#define CLRT_RENDER_LIGHTS_H

#include "light_files.h"

/* Sample j of `light` from point p; u is the pair of random numbers that places the sample when
 * the kind reads one (light_is_sampled). */
CLRT_INLINE LightSample sample_light(__global const Light* light, uint j, float3 p, float2 u) {
  switch (light->kind) {
#define CLRT_LIGHT_SAMPLE_CASE(KIND, name) \
    case CLRT_LIGHT_##KIND: return name##_light_sample(light, j, p, u);
    CLRT_LIGHT_KINDS(CLRT_LIGHT_SAMPLE_CASE)
#undef CLRT_LIGHT_SAMPLE_CASE
  }
  return point_light_sample(light, j, p, u);
}

/* Whether sample_light reads its random numbers for `light`, so that the others need not draw
 * them. */
CLRT_INLINE bool light_is_sampled(__global const Light* light) {
  switch (light->kind) {
#define CLRT_LIGHT_PAIR_CASE(KIND, name) \
    case CLRT_LIGHT_##KIND: return name##_light_reads_pair();
    CLRT_LIGHT_KINDS(CLRT_LIGHT_PAIR_CASE)
#undef CLRT_LIGHT_PAIR_CASE
  }
  return false;
}

/* Where o + t d with t in (tmin, tmax) crosses `light`, if paths can hit it. */
CLRT_INLINE LightCrossing light_crossing(__global const Light* light, float3 o, float3 d, float tmin,
                                         float tmax) {
  switch (light->kind) {
#define CLRT_LIGHT_CROSSING_CASE(KIND, name) \
    case CLRT_LIGHT_##KIND: return name##_light_crossing(light, o, d, tmin, tmax);
    CLRT_LIGHT_KINDS(CLRT_LIGHT_CROSSING_CASE)
#undef CLRT_LIGHT_CROSSING_CASE
  }
  return no_crossing();
}

#endif
