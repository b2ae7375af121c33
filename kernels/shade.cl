/* shade: the transport step (render/transport_step.h: Whitted or path) at every hit of a chunk
 * of the queue, its shadow and child rays written to slots for compaction.
 * In: rays and hits [first, first + count).
 * Out, for ray i of the queue:
 *   colour[i]      its own colour so far (the step's result; shadow rays add theirs later);
 *   shadow slots   (trace and path modes) slot (i - first) * shadow_samples + s for light sample
 *                  s, flag set when the sample can contribute; compacted, then tested by
 *                  shadow.cl;
 *   spawn slots    (trace and path modes, depth < max depth) 2i reflection (a path's next
 *                  ray), 2i + 1 refraction, flag set when spawned. Compacted into the next
 *                  pass's queue.
 * shade_sorted does the same for the rays of one shading class (sort_hits.cl) in the order the
 * class lists them: every output still goes to ray i's own slots, so the order of shading
 * never changes a bit of the image. */
#include "render/transport_step.h"

/* The parameters both kernels take before and after their own, as the host's ShadeInputs and
 * ShadeOutputs (src/render/stage_args.hpp) bind them. */
#define SHADE_INPUT_PARAMS __global const RenderParams* params, __global const Material* materials, TEXTURE_PARAMS, __global const Light* lights, __global const Ray* rays, __global const Hit* hits
#define SHADE_INPUT_ARGS params, materials, TEXTURE_ARGS, lights, rays, hits
#define SHADE_OUTPUT_PARAMS __global float4* colour, __global ShadowRay* shadow_slots, __global uint* shadow_flags, __global Ray* spawn_slots, __global uint* spawn_flags
#define SHADE_OUTPUT_ARGS colour, shadow_slots, shadow_flags, spawn_slots, spawn_flags

CLRT_INLINE void shade_ray(SHADE_INPUT_PARAMS, uint first, uint i, SHADE_OUTPUT_PARAMS) {
  const size_t slots = params->shadow_samples;
  const size_t local_index = i - first;
  RaySink sink = queue_sink(shadow_slots + local_index * slots, shadow_flags + local_index * slots,
                            spawn_slots + CLRT_CHILD_SLOTS * i, spawn_flags + CLRT_CHILD_SLOTS * i);
  if (CLRT_TRANSPORT_SPAWNS) {
    for (size_t s = 0; s < slots; ++s) sink.shadow_flags[s] = 0u;
    for (uint s = 0; s < CLRT_CHILD_SLOTS; ++s) sink.child_flags[s] = 0u;
  }
  const Ray ray = rays[i];
  const Hit hit = hits[i];
  colour[i] = as_f4(transport_step(&ray, &hit, materials, TEXTURE_ARGS, lights, params, i, &sink));
}

__kernel void shade(SHADE_INPUT_PARAMS, uint first, uint count, SHADE_OUTPUT_PARAMS) {
  const uint j = get_global_id(0);
  if (j >= count) return;
  shade_ray(SHADE_INPUT_ARGS, first, first + j, SHADE_OUTPUT_ARGS);
}

/* order[j].x for j < *class_count: the queue indices of the class's rays (compacted on the
 * device; the count stays there). */
__kernel void shade_sorted(SHADE_INPUT_PARAMS, uint first, __global const uint4* order,
                           __global const uint* class_count, SHADE_OUTPUT_PARAMS) {
  const uint j = get_global_id(0);
  if (j >= *class_count) return;
  shade_ray(SHADE_INPUT_ARGS, first, order[j].x, SHADE_OUTPUT_ARGS);
}
