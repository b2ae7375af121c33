/* shade: the Whitted local terms at every hit of a chunk of the queue, and the rays it spawns.
 * In: rays and hits [first, first + count).
 * Out, for ray i of the queue:
 *   colour[i]      its own colour so far: background on a miss; else the ambient term, plus
 *                  (cast mode) every light's term, lights counting as unblocked;
 *   shadow slots   (trace mode) slot (i - first) * shadow_samples + s for light sample s, flag
 *                  set when the sample can contribute; compacted, then tested by shadow.cl;
 *   spawn slots    (trace mode, depth < max depth) 2i reflection, 2i + 1 refraction, flag set
 *                  when spawned. Compacted into the next pass's queue.
 * The terms themselves are render/shade_point.h's, which the megakernel calls too. */
#include "render/shade_point.h"

__kernel void shade(__global const RenderParams* params, __global const Material* materials,
                    __global const Light* lights, __global const Ray* rays,
                    __global const Hit* hits, uint first, uint count, __global float4* colour,
                    __global ShadowRay* shadow_slots, __global uint* shadow_flags,
                    __global Ray* spawn_slots, __global uint* spawn_flags) {
  const uint local_index = get_global_id(0);
  if (local_index >= count) return;
  const uint i = first + local_index;
  const bool trace = params->mode == CLRT_MODE_TRACE;
  const size_t slots = params->shadow_samples;
  __global ShadowRay* my_shadows = shadow_slots + local_index * slots;
  __global uint* my_shadow_flags = shadow_flags + local_index * slots;
  if (trace) {
    for (size_t s = 0; s < slots; ++s) my_shadow_flags[s] = 0u;
    spawn_flags[2 * i] = 0u;
    spawn_flags[2 * i + 1] = 0u;
  }

  const Ray ray = rays[i];
  const Hit hit = hits[i];
  if (hit.instance == CLRT_NO_HIT) {
    colour[i] = as_f4(miss_colour(&ray, params));
    return;
  }
  const ShadePoint sp = shade_point(&ray, &hit, materials);
  float3 c = ambient_colour(&sp, materials, params);
  for (uint l = 0; l < params->light_count; ++l) {
    __global const Light* light = &lights[l];
    for (uint j = 0; j < light->samples; ++j) {
      LightSample ls;
      const float3 term = light_term(&sp, materials, light, j, ray.path, &ls);
      if (all(term == (float3)(0.0f))) continue;
      const uint slot = light->first_sample + j;
      if (trace) {
        my_shadows[slot] = shadow_ray_to(&sp, &ls, term, i, params->epsilon);
        my_shadow_flags[slot] = 1u;
      } else {
        c += term;
      }
    }
  }
  colour[i] = as_f4(c);
  if (!trace || ray.depth >= params->max_depth) return;
  Ray reflected, refracted;
  const uint spawned = spawn_children(&ray, &sp, materials, params, &reflected, &refracted);
  if (spawned & CLRT_SPAWN_REFLECTION) {
    spawn_slots[2 * i] = reflected;
    spawn_flags[2 * i] = 1u;
  }
  if (spawned & CLRT_SPAWN_REFRACTION) {
    spawn_slots[2 * i + 1] = refracted;
    spawn_flags[2 * i + 1] = 1u;
  }
}
