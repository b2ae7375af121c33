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

CLRT_INLINE void shade_ray(__global const RenderParams* params, __global const Material* materials,
                           __global const Light* lights, __global const Ray* rays,
                           __global const Hit* hits, uint first, uint i, __global float4* colour,
                           __global ShadowRay* shadow_slots, __global uint* shadow_flags,
                           __global Ray* spawn_slots, __global uint* spawn_flags) {
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
  colour[i] = as_f4(transport_step(&ray, &hit, materials, lights, params, i, &sink));
}

__kernel void shade(__global const RenderParams* params, __global const Material* materials,
                    __global const Light* lights, __global const Ray* rays,
                    __global const Hit* hits, uint first, uint count, __global float4* colour,
                    __global ShadowRay* shadow_slots, __global uint* shadow_flags,
                    __global Ray* spawn_slots, __global uint* spawn_flags) {
  const uint j = get_global_id(0);
  if (j >= count) return;
  shade_ray(params, materials, lights, rays, hits, first, first + j, colour, shadow_slots,
            shadow_flags, spawn_slots, spawn_flags);
}

/* order[j].x for j < *class_count: the queue indices of the class's rays (compacted on the
 * device; the count stays there). */
__kernel void shade_sorted(__global const RenderParams* params, __global const Material* materials,
                           __global const Light* lights, __global const Ray* rays,
                           __global const Hit* hits, uint first, __global const uint4* order,
                           __global const uint* class_count, __global float4* colour,
                           __global ShadowRay* shadow_slots, __global uint* shadow_flags,
                           __global Ray* spawn_slots, __global uint* spawn_flags) {
  const uint j = get_global_id(0);
  if (j >= *class_count) return;
  shade_ray(params, materials, lights, rays, hits, first, order[j].x, colour, shadow_slots,
            shadow_flags, spawn_slots, spawn_flags);
}
