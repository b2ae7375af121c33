/* The transport step of the render's mode, the one both integrators' kernels call: the Whitted
 * step (cast and trace modes) or a path-tracing vertex (path mode). The mode is the same for
 * every work-item, so the branch never diverges. */
#ifndef CLRT_RENDER_TRANSPORT_STEP_H
#define CLRT_RENDER_TRANSPORT_STEP_H

#include "path_step.h"
#include "whitted_step.h"

CLRT_INLINE float3 transport_step(const Ray* ray, const Hit* hit, __global const Material* materials,
                                  __global const Light* lights, __global const RenderParams* params,
                                  uint owner, WhittedSink* sink) {
  if (params->mode == CLRT_MODE_PATH) return path_step(ray, hit, materials, lights, params, owner, sink);
  return whitted_step(ray, hit, materials, lights, params, owner, sink);
}

#endif
