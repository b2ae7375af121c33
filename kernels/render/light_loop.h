/* The loop over a shading point's light samples, one for every transport model: lights in table
 * order and each light's samples in order, the order in which accumulate.cl sums their shadow
 * rays (plain counted loops: a resumable cursor over both, tried first, ran forever now and then
 * on Intel's CPU runtime). A zero term (N.L <= 0, outside a spot's cone, no smooth lobe) sends no
 * shadow ray: it could not change the image. A program holds one transport model
 * (render/transport_step.h), which defines what is declared here. */
#ifndef CLRT_RENDER_LIGHT_LOOP_H
#define CLRT_RENDER_LIGHT_LOOP_H

#include "lights.h"
#include "ray_sink.h"
#include "shade_point.h"

/* What the model knows of a shading point. */
typedef struct TransportVertex TransportVertex;
/* The pair of random numbers for light sample `use` (of a kind that reads one: light_is_sampled). */
CLRT_INLINE float2 transport_light_pair(const TransportVertex* vertex, uint use);
/* What the sample adds if nothing blocks it. */
CLRT_INLINE float3 transport_light_term(const TransportVertex* vertex, __global const Light* light,
                                        const LightSample* ls);

/* Adds each light sample's term to *colour at once when shadows_tested is false (cast mode), and
 * otherwise hands its shadow ray, at the owner ray's time, to the sink. */
CLRT_INLINE void gather_light_samples(const TransportVertex* vertex, const ShadePoint* sp,
                                      __global const Light* lights,
                                      __global const RenderParams* params, bool shadows_tested,
                                      uint owner, float time, RaySink* sink, float3* colour) {
  for (uint l = 0; l < params->light_count; ++l) {
    __global const Light* light = &lights[l];
    for (uint j = 0; j < light->samples; ++j) {
      const uint use = light->first_sample + j;
      const float2 u = light_is_sampled(light) ? transport_light_pair(vertex, use) : (float2)(0.0f);
      const LightSample ls = sample_light(light, j, sp->p, u);
      const float3 term = transport_light_term(vertex, light, &ls);
      if (all(term == (float3)(0.0f))) continue;
      if (!shadows_tested) {
        *colour += term;
        continue;
      }
      const ShadowRay sr = shadow_ray_to(sp, &ls, term, owner, time, params->epsilon);
      sink_shadow(sink, use, &sr, colour);
    }
  }
}

#endif
