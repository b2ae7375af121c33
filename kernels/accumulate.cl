/* Deterministic accumulation without float atomics. Queues are sorted by owner (shadow rays by
 * the ray they light, rays by their camera sample): the first item of each run of equal owners
 * adds the whole run in queue order and is the only writer of that owner's entry. The order of
 * every sum therefore depends only on the ray tree of one sample, never on threads, work-group
 * sizes or how many samples share a wave. */
#include "render/common.h"

/* colour[owner] += the visible contributions of its shadow rays, in light-sample order. The
 * queue's length *count is the one compaction left on the device (see shadow.cl). */
__kernel void gather_shadows(__global const ShadowRay* shadows, __global const float4* visible,
                             __global const uint* count_on_device, __global float4* colour) {
  const uint i = get_global_id(0);
  const uint count = *count_on_device;
  if (i >= count) return;
  const uint owner = shadows[i].owner;
  if (i > 0 && shadows[i - 1].owner == owner) return;
  float4 sum = colour[owner];
  for (uint j = i; j < count && shadows[j].owner == owner; ++j) sum += visible[j];
  colour[owner] = sum;
}

/* sample_colour[s] += the colours of this pass's rays of sample s, in queue order. */
__kernel void accumulate_samples(__global const Ray* rays, __global const float4* colour,
                                 uint count, __global float4* sample_colour) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const uint sample = rays[i].sample;
  if (i > 0 && rays[i - 1].sample == sample) return;
  float4 sum = colour[i];
  for (uint j = i + 1; j < count && rays[j].sample == sample; ++j) sum += colour[j];
  sample_colour[sample] += sum;
}

/* pixels[p] = the mean of its samples (unclamped: clamping happens once, when quantising). */
__kernel void resolve(__global const float4* sample_colour, uint samples, uint pixel_count,
                      __global float4* pixels) {
  const uint p = get_global_id(0);
  if (p >= pixel_count) return;
  float4 sum = sample_colour[(size_t)p * samples];
  for (uint k = 1; k < samples; ++k) sum += sample_colour[(size_t)p * samples + k];
  pixels[p] = sum / (float)samples;
}

/* Rays of each kind in the queue, for --stats, added to the current wave's counts[kind]. Each
 * work-item counts a run of `chunk` rays and adds its three totals with integer atomics (exact
 * in any order): one atomic per ray made this kernel cost as much as shading. */
__kernel void count_kinds(__global const Ray* rays, uint count, uint chunk, __global uint* counts) {
  const uint begin = get_global_id(0) * chunk;
  if (begin >= count) return;
  const uint end = min(begin + chunk, count);
  uint per_kind[3] = {0u, 0u, 0u};
  for (uint i = begin; i < end; ++i) ++per_kind[rays[i].kind];
  for (uint k = 0; k < 3; ++k)
    if (per_kind[k]) atomic_add(&counts[k], per_kind[k]);
}

/* A finished wave's counts join the render's (counts[3 + kind]) and restart from zero; the
 * host reads them once per range of pixels instead of waiting for them every pass. */
__kernel void commit_kind_counts(__global uint* counts) {
  const uint k = get_global_id(0);
  if (k >= 3) return;
  counts[3 + k] += counts[k];
  counts[k] = 0;
}
