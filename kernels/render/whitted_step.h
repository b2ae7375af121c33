/* One Whitted transport step, written once for both integrators: what a traced ray contributes
 * itself, and the shadow and child rays it hands to its sink (render/whitted_sink.h), which
 * queues them (wavefront) or follows them at once (megakernel). The children are handed over
 * refraction first, so that a depth-first stack pops the reflection first: the tree order
 * accumulate.cl sums in. Returns the ray's own colour: its miss colour, or its ambient term plus
 * (cast mode) every light's term or (trace mode) what the sink added. */
#ifndef CLRT_RENDER_WHITTED_STEP_H
#define CLRT_RENDER_WHITTED_STEP_H

#include "shade_point.h"
#include "whitted_sink.h"

CLRT_INLINE float3 whitted_step(const Ray* ray, const Hit* hit, __global const Material* materials,
                                __global const Light* lights, __global const RenderParams* params,
                                uint owner, WhittedSink* sink) {
  if (hit->instance == CLRT_NO_HIT) return miss_colour(ray, params);
  const bool trace = params->mode == CLRT_MODE_TRACE;
  const ShadePoint sp = shade_point(ray, hit, materials);
  float3 c = ambient_colour(&sp, materials, params);
  for (uint l = 0; l < params->light_count; ++l) {
    __global const Light* light = &lights[l];
    for (uint j = 0; j < light->samples; ++j) {
      LightSample ls;
      const float3 term = light_term(&sp, materials, light, j, ray->path, &ls);
      if (all(term == (float3)(0.0f))) continue;
      if (trace) {
        const ShadowRay sr = shadow_ray_to(&sp, &ls, term, owner, params->epsilon);
        sink_shadow(sink, light->first_sample + j, &sr, &c);
      } else {
        c += term;
      }
    }
  }
  if (!trace || ray->depth >= params->max_depth) return c;
  Ray reflected, refracted;
  const uint spawned = spawn_children(ray, &sp, materials, params, &reflected, &refracted);
  if (spawned & CLRT_SPAWN_REFRACTION) sink_child(sink, CLRT_SPAWN_REFRACTION, &refracted);
  if (spawned & CLRT_SPAWN_REFLECTION) sink_child(sink, CLRT_SPAWN_REFLECTION, &reflected);
  return c;
}

#endif
