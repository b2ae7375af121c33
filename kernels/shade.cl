/* shade: the Whitted local terms at every hit of a chunk of the queue, and the rays it spawns.
 * In: rays and hits [first, first + count).
 * Out, for ray i of the queue:
 *   colour[i]      its own colour so far: background on a miss; else the ambient term, plus
 *                  (cast mode) every light's term, lights counting as unblocked;
 *   shadow slots   (trace mode) slot (i - first) * shadow_samples + s for light sample s, flag
 *                  set when the sample can contribute; compacted, then tested by shadow.cl;
 *   spawn slots    (trace mode, depth < max depth) 2i reflection, 2i + 1 refraction, flag set
 *                  when spawned; total internal reflection sends the kt share along the
 *                  reflection ray. Compacted into the next pass's queue. */
#include "render/common.h"
#include "render/lights.h"
#include "render/secondary.h"
#include "render/whitted.h"

/* The point a secondary or shadow ray leaves from: p moved by epsilon along the geometric
 * normal, to the side the ray leaves through. */
inline float3 offset_origin(float3 p, float3 ng, float3 dir, float epsilon) {
  return p + (dot(ng, dir) >= 0.0f ? epsilon : -epsilon) * ng;
}

inline void spawn(const Ray* ray, __global const Material* m, __global const RenderParams* params,
                  float3 p, float3 ng, float3 n, bool front, uint i, __global Ray* spawn_slots,
                  __global uint* spawn_flags) {
  const float3 d = xyz(ray->dir);
  const float3 r = reflect_dir(d, n);
  float reflect_share = m->kr;
  float3 t;
  const float eta = front ? 1.0f / m->ior : m->ior;
  const bool refracts = m->kt > 0.0f && refract_dir(d, n, eta, &t);
  if (m->kt > 0.0f && !refracts) reflect_share += m->kt;
  spawn_flags[2 * i] = reflect_share > 0.0f;
  spawn_flags[2 * i + 1] = refracts;
  if (reflect_share > 0.0f)
    spawn_slots[2 * i] = child_ray(ray, offset_origin(p, ng, r, params->epsilon), r, reflect_share,
                                   CLRT_BRANCH_REFLECT, CLRT_RAY_REFLECTION);
  if (refracts)
    spawn_slots[2 * i + 1] = child_ray(ray, offset_origin(p, ng, t, params->epsilon), t, m->kt,
                                       CLRT_BRANCH_REFRACT, CLRT_RAY_REFRACTION);
}

__kernel void shade(__global const RenderParams* params, __global const Material* materials,
                    __global const Light* lights, __global const Ray* rays,
                    __global const Hit* hits, uint first, uint count, __global float4* colour,
                    __global ShadowRay* shadow_slots, __global uint* shadow_flags,
                    __global Ray* spawn_slots, __global uint* spawn_flags) {
  const uint local_index = get_global_id(0);
  if (local_index >= count) return;
  const uint i = first + local_index;
  const bool trace = params->mode == CLRT_MODE_TRACE;
  const uint slots = params->shadow_samples;
  __global uint* my_shadow_flags = shadow_flags + (size_t)local_index * slots;
  if (trace) {
    for (uint s = 0; s < slots; ++s) my_shadow_flags[s] = 0u;
    spawn_flags[2 * i] = 0u;
    spawn_flags[2 * i + 1] = 0u;
  }

  const Ray ray = rays[i];
  const Hit hit = hits[i];
  const float3 weight = xyz(ray.weight);
  if (hit.instance == CLRT_NO_HIT) {
    colour[i] = as_f4(weight * xyz(params->background));
    return;
  }

  const float3 d = xyz(ray.dir);
  const float3 p = xyz(ray.origin) + hit.geometric_normal.w * d;
  const bool front = dot(xyz(hit.geometric_normal), d) < 0.0f;
  const float3 ng = front ? xyz(hit.geometric_normal) : -xyz(hit.geometric_normal);
  /* Vertex normals may disagree with the winding (NFF patches, many OBJ exports): the shading
   * normal is first turned into the geometric normal's hemisphere, then faces the ray with it. */
  const float3 ns = xyz(hit.shading_normal);
  const float3 n = dot(ns, ng) < 0.0f ? -ns : ns;
  const float3 v = -d;
  __global const Material* m = &materials[hit.material];
  const float3 base = weight * local_share(m);

  float3 c = base * m->ka * xyz(params->ambient) * xyz(m->color);
  uint slot = 0;
  for (uint l = 0; l < params->light_count; ++l) {
    __global const Light* light = &lights[l];
    for (uint j = 0; j < light->samples; ++j, ++slot) {
      const LightSample ls = sample_light(light, j, p, ray.path);
      const float3 term = base * direct_term(m, n, v, ls.to_light, ls.intensity);
      if (all(term == (float3)(0.0f))) continue;
      if (!trace) {
        c += term;
        continue;
      }
      const float3 origin = offset_origin(p, ng, ls.to_light, params->epsilon);
      ShadowRay sr;
      sr.origin = (f4)(origin, ls.distance == INFINITY ? INFINITY : distance(origin, ls.position));
      sr.dir = as_f4(ls.distance == INFINITY ? ls.to_light : normalize(ls.position - origin));
      sr.contribution = as_f4(term);
      sr.owner = i;
      shadow_slots[(size_t)local_index * slots + slot] = sr;
      my_shadow_flags[slot] = 1u;
    }
  }
  colour[i] = as_f4(c);
  if (trace && ray.depth < params->max_depth)
    spawn(&ray, m, params, p, ng, n, front, i, spawn_slots, spawn_flags);
}
