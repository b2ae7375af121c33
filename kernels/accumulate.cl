/* Deterministic accumulation without float atomics, in the order both integrators follow
 * (the megakernel in megakernel.cl adds in exactly this order):
 *   1. a ray's colour: its ambient term + its surface's emission (or its miss colour), then
 *      + each unblocked light sample's term in light-sample order (a blocked sample adds 0);
 *   2. a sample's level d: the colours of its rays of depth d, left to right in the ray tree
 *      (reflection before refraction at every branch), added from the first;
 *   3. a sample's colour: 0 + level 0 + level 1 + ... (levels without rays add nothing);
 *   4. a pixel: sample 0 + sample 1 + ..., divided by the sample count, across rounds.
 * In the wavefront, queues are sorted by owner (shadow rays by the ray they light, rays by their
 * camera sample, and within a sample in tree order, since compaction is stable): the first item
 * of each run of equal owners adds the whole run in queue order and is the only writer of that
 * owner's entry. Every sum therefore depends only on one sample's ray tree, never on threads,
 * work-group sizes, how many samples share a wave, or the integrator. */
#include "render/common.h"

/* colour[owner] += the visible contributions of its shadow rays, in light-sample order. The
 * queue's length *count is the one compaction left on the device (see shadow.cl). */
__kernel void gather_shadows(__global const ShadowRay* shadows, __global const float4* visible,
                             __global const uint* count, __global float4* colour) {
  const uint i = get_global_id(0);
  const uint n = *count;
  if (i >= n) return;
  const uint owner = shadows[i].owner;
  if (i > 0 && shadows[i - 1].owner == owner) return;
  float4 sum = colour[owner];
  for (uint j = i; j < n && shadows[j].owner == owner; ++j) sum += visible[j];
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

/* A camera sample's colour scaled down, hue kept, so that its largest channel is at most
 * max_value (pbrt-v4's maxcomponentvalue): a firefly costs its pixel at most max_value / spp.
 * INFINITY leaves every sample as it is. */
CLRT_INLINE float4 clamp_sample(float4 c, float max_value) {
  const float largest = fmax(c.x, fmax(c.y, c.z));
  return largest > max_value ? c * (max_value / largest) : c;
}

/* A wave's pixels after one round of their samples (src/render/sample_rounds.hpp): pixels[p]
 * comes in holding the sum of the samples before first_sample (unless this is the first round)
 * and leaves holding the sum up to this round's last sample (unclamped: clamping happens once,
 * when quantising); the host divides by the sample count after the last round, so the sums
 * of a finished render are there to go on from (clrt --resume). Each sum is sample 0 + sample
 * 1 + ... in that order, so how the samples are split into rounds never changes a bit. Each
 * sample is clamped first (clamp_sample). */
__kernel void resolve(__global const float4* sample_colour, uint samples, uint first_sample,
                      uint pixel_count, float max_sample_value, __global float4* pixels) {
  const uint p = get_global_id(0);
  if (p >= pixel_count) return;
  const size_t base = (size_t)p * samples;
  const float4 first = clamp_sample(sample_colour[base], max_sample_value);
  float4 sum = first_sample == 0u ? first : pixels[p] + first;
  for (uint k = 1; k < samples; ++k) sum += clamp_sample(sample_colour[base + k], max_sample_value);
  pixels[p] = sum;
}
