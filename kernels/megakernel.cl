/* megakernel: the integrator to compare the wavefront with (Laine, Karras and Aila,
 * "Megakernels Considered Harmful", HPG 2013). One work-item per camera sample of a wave walks
 * the sample's whole ray tree (a path, in path mode) depth first with a private stack, running
 * the wavefront's own stages (render/camera.h, scene_closest_hit, the transport step of
 * render/transport_step.h with a sink that tests shadow rays at once and pushes children), and sums the contributions
 * in the order accumulate.cl writes down: per tree level, left to right (a depth-first walk that takes the
 * reflection before the refraction meets each level's rays in that order), then level by
 * level. It therefore produces the wavefront's bits.
 * In: a wave as for generate. Out: sample_colour[i] for camera sample i, and ray_counts[i]
 * (CLRT_RAY_KINDS counts per sample, for --stats). */
#include "render/camera.h"

/* The deepest ray tree the private stack holds: the host refuses a larger maximum depth for
 * this integrator. Set per device class by the program options (src/device/device_tuning.cpp). */
#ifndef CLRT_MEGAKERNEL_DEPTH
#define CLRT_MEGAKERNEL_DEPTH 16
#endif
#if CLRT_MEGAKERNEL_DEPTH > 62
#error "CLRT_MEGAKERNEL_DEPTH must fit the 64-bit mask of levels"
#endif

#include "render/transport_step.h"

__kernel void megakernel(SCENE_PARAMS, __global const RenderParams* params,
                         __global const Camera* camera, __global const Material* materials, TEXTURE_PARAMS,
                         __global const Light* lights, uint region_x, uint region_y,
                         uint region_width, uint first_pixel, uint first_sample,
                         uint pixel_samples, uint sample_count, __global float4* sample_colour, __global uint* ray_counts) {
  const uint i = get_global_id(0);
  if (i >= sample_count) return;
  const Camera cam = *camera;
  /* Depth first, each branch pushes its refraction then its reflection: one pending ray per
   * level on the current path, two at the deepest, so max depth + 1 entries suffice. Levels
   * run to max depth + 1: a path's last ray, drawn at the cap, only gathers light. */
  Ray stack[CLRT_MEGAKERNEL_DEPTH + 1];
  float3 level[CLRT_MEGAKERNEL_DEPTH + 2];
  ulong levels_seen = 0ul;
  uint counts[CLRT_RAY_KINDS] = {0u};
  uint top = 0;
  const SceneTables scene = {SCENE_ARGS};
  RaySink sink = stack_sink(scene, params->epsilon, stack, &top, counts);
  stack[top++] = wave_camera_ray(&cam, region_x, region_y, region_width, first_pixel,
                                 first_sample, pixel_samples, i);
  while (top > 0) {
    const Ray ray = stack[--top];
    ++counts[CLRT_RAY_KIND(ray)];
    Hit hit;
    scene_closest_hit(SCENE_ARGS, vload3(0, ray.origin), vload3(0, ray.dir), ray.time, params->epsilon,
                      INFINITY, &hit);
    const float3 c = transport_step(&ray, &hit, materials, TEXTURE_ARGS, lights, params, i, &sink);
    const uint depth = CLRT_RAY_DEPTH(ray);
    const ulong bit = 1ul << depth;
    level[depth] = (levels_seen & bit) ? level[depth] + c : c;
    levels_seen |= bit;
  }
  float3 total = (float3)(0.0f);
  for (uint d = 0; d <= CLRT_MEGAKERNEL_DEPTH + 1; ++d)
    if (levels_seen & (1ul << d)) total += level[d];
  sample_colour[i] = as_f4(total);
  for (uint k = 0; k < CLRT_RAY_KINDS; ++k) ray_counts[i * CLRT_RAY_KINDS + k] = counts[k];
}
