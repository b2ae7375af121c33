/* megakernel: the integrator to compare the wavefront with (Laine, Karras and Aila,
 * "Megakernels Considered Harmful", HPG 2013). One work-item per camera sample of a wave walks
 * the sample's whole Whitted ray tree depth first with a private stack, calling the wavefront's
 * own stage functions (render/camera.h, scene_closest_hit, render/shade_point.h,
 * render/shadow_test.h) and random numbers, and sums the contributions in the order
 * accumulate.cl writes down: per tree level, left to right (a depth-first walk that takes the
 * reflection before the refraction meets each level's rays in that order), then level by
 * level. It therefore produces the wavefront's bits.
 * In: a wave as for generate. Out: sample_colour[i] for camera sample i, and ray_counts[i]
 * (CLRT_RAY_KINDS counts per sample, for --stats). */
#include "render/camera.h"
#include "render/shade_point.h"
#include "render/shadow_test.h"

/* The deepest ray tree the private stack holds: the host refuses a larger maximum depth for
 * this integrator. Set per device class by the program options (src/device/device_tuning.cpp). */
#ifndef CLRT_MEGAKERNEL_DEPTH
#define CLRT_MEGAKERNEL_DEPTH 16
#endif
#if CLRT_MEGAKERNEL_DEPTH > 63
#error "CLRT_MEGAKERNEL_DEPTH must fit the 64-bit mask of levels"
#endif

__kernel void megakernel(SCENE_PARAMS, __global const RenderParams* params,
                         __global const Camera* camera, __global const Material* materials,
                         __global const Light* lights, uint region_x, uint region_y,
                         uint region_width, uint first_pixel, uint sample_count,
                         __global float4* sample_colour, __global uint* ray_counts) {
  const uint i = get_global_id(0);
  if (i >= sample_count) return;
  const Camera cam = *camera;
  const bool trace = params->mode == CLRT_MODE_TRACE;
  /* Depth first, each branch pushes its refraction then its reflection: one pending ray per
   * level on the current path, two at the deepest, so max depth + 1 entries suffice. */
  Ray stack[CLRT_MEGAKERNEL_DEPTH + 1];
  float3 level[CLRT_MEGAKERNEL_DEPTH + 1];
  ulong levels_seen = 0ul;
  uint counts[CLRT_RAY_KINDS] = {0u};
  uint top = 0;
  stack[top++] = wave_camera_ray(&cam, region_x, region_y, region_width, first_pixel, i);
  while (top > 0) {
    const Ray ray = stack[--top];
    ++counts[ray.kind];
    Hit hit;
    scene_closest_hit(SCENE_ARGS, xyz(ray.origin), xyz(ray.dir), params->epsilon, INFINITY, &hit);
    float3 c;
    if (hit.instance == CLRT_NO_HIT) {
      c = miss_colour(&ray, params);
    } else {
      const ShadePoint sp = shade_point(&ray, &hit, materials);
      c = ambient_colour(&sp, materials, params);
      for (uint l = 0; l < params->light_count; ++l) {
        __global const Light* light = &lights[l];
        for (uint j = 0; j < light->samples; ++j) {
          LightSample ls;
          const float3 term = light_term(&sp, materials, light, j, ray.path, &ls);
          if (all(term == (float3)(0.0f))) continue;
          if (trace) {
            const ShadowRay sr = shadow_ray_to(&sp, &ls, term, i, params->epsilon);
            ++counts[CLRT_RAY_SHADOW];
            c += xyz(shadow_visible(SCENE_ARGS, params->epsilon, &sr));
          } else {
            c += term;
          }
        }
      }
      if (trace && ray.depth < params->max_depth) {
        Ray reflected, refracted;
        const uint spawned = spawn_children(&ray, &sp, materials, params, &reflected, &refracted);
        if (spawned & CLRT_SPAWN_REFRACTION) stack[top++] = refracted;
        if (spawned & CLRT_SPAWN_REFLECTION) stack[top++] = reflected;
      }
    }
    const ulong bit = 1ul << ray.depth;
    level[ray.depth] = (levels_seen & bit) ? level[ray.depth] + c : c;
    levels_seen |= bit;
  }
  float3 total = (float3)(0.0f);
  for (uint d = 0; d <= CLRT_MEGAKERNEL_DEPTH; ++d)
    if (levels_seen & (1ul << d)) total += level[d];
  sample_colour[i] = as_f4(total);
  for (uint k = 0; k < CLRT_RAY_KINDS; ++k) ray_counts[i * CLRT_RAY_KINDS + k] = counts[k];
}
