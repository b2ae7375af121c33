/* shadow: an any-hit test of every shadow ray of the compacted queue.
 * In: shadows[0, *count); the count stays on the device where compaction wrote it, so the host
 * launches over an upper bound instead of waiting to read it. Out: visible[i] = the ray's
 * contribution when unblocked, else zero; gather_shadows (accumulate.cl) adds them up. */
#include "render/shadow_test.h"

__kernel void shadow(SCENE_PARAMS, __global const RenderParams* params,
                     __global const ShadowRay* shadows, __global const uint* count,
                     __global float4* visible) {
  const uint i = get_global_id(0);
  if (i >= *count) return;
  const ShadowRay s = shadows[i];
  visible[i] = shadow_visible(SCENE_ARGS, params->epsilon, &s);
}
