/* Rays by kind for --stats, counted on the device so that the host never waits for them in
 * the middle of a pass. Counts go through three tables:
 *   partial  uint[rows][CLRT_RAY_KINDS]: per chunk of a queue, or per chunk of the megakernel's
 *            per-sample rows (fold_ray_counts);
 *   staging  ulong[passes][CLRT_RAY_KINDS]: the current wave's, dropped if the wave is retried;
 *   totals   ulong[passes][CLRT_RAY_KINDS]: the render's, read once at the end.
 * The adding kernels run as one work-item on an in-order queue: 64-bit sums without atomics
 * (a wave with many area-light samples can pass 2^32 shadow rays). */
#include "render/common.h"

__kernel void count_ray_kinds(__global const Ray* rays, uint count, uint chunk,
                              __global uint* partial) {
  const uint c = get_global_id(0);
  const uint begin = c * chunk;
  if (begin >= count) return;
  const uint end = min(begin + chunk, count);
  uint per_kind[CLRT_RAY_KINDS] = {0u};
  for (uint i = begin; i < end; ++i) ++per_kind[CLRT_RAY_KIND(rays[i])];
  for (uint k = 0; k < CLRT_RAY_KINDS; ++k) partial[c * CLRT_RAY_KINDS + k] = per_kind[k];
}

/* partial[c] = the sum of rows [c * chunk, (c + 1) * chunk) of the megakernel's per-sample
 * counts: the serial sum that follows then adds a few rows, not one per sample. */
__kernel void fold_ray_counts(__global const uint* rows, uint row_count, uint chunk,
                              __global uint* partial) {
  const uint c = get_global_id(0);
  const uint begin = c * chunk;
  if (begin >= row_count) return;
  const uint end = min(begin + chunk, row_count);
  uint sum[CLRT_RAY_KINDS] = {0u};
  for (uint r = begin; r < end; ++r)
    for (uint k = 0; k < CLRT_RAY_KINDS; ++k) sum[k] += rows[r * CLRT_RAY_KINDS + k];
  for (uint k = 0; k < CLRT_RAY_KINDS; ++k) partial[c * CLRT_RAY_KINDS + k] = sum[k];
}

__kernel void add_ray_kinds(__global const uint* partial, uint rows, uint pass,
                            __global ulong* staging) {
  if (get_global_id(0) != 0) return;
  ulong sum[CLRT_RAY_KINDS] = {0ul};
  for (uint r = 0; r < rows; ++r)
    for (uint k = 0; k < CLRT_RAY_KINDS; ++k) sum[k] += partial[r * CLRT_RAY_KINDS + k];
  for (uint k = 0; k < CLRT_RAY_KINDS; ++k) staging[pass * CLRT_RAY_KINDS + k] += sum[k];
}

__kernel void add_shadow_rays(__global const uint* count, uint pass, __global ulong* staging) {
  if (get_global_id(0) != 0) return;
  staging[pass * CLRT_RAY_KINDS + CLRT_RAY_SHADOW] += *count;
}

__kernel void commit_ray_counts(uint entries, __global ulong* staging, __global ulong* totals) {
  const uint e = get_global_id(0);
  if (e >= entries) return;
  totals[e] += staging[e];
  staging[e] = 0ul;
}
