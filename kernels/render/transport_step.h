/* The transport step both integrators' kernels call, of the one transport model the program is
 * built for: the renderer builds a program per mode, with -DCLRT_TRANSPORT=CLRT_MODE_*
 * (src/render/renderer_program.cpp), so no kernel branches on the mode and each holds only its
 * model's code. */
#ifndef CLRT_RENDER_TRANSPORT_STEP_H
#define CLRT_RENDER_TRANSPORT_STEP_H

#ifndef CLRT_TRANSPORT
#error "build the renderer's program with -DCLRT_TRANSPORT=N, N one of the CLRT_MODE_* values"
#endif

/* What both models include, outside the choice below: the kernel source is assembled with each
 * file expanded once, where it is first included (src/device/kernel_source.cpp). The Phong lobe
 * draws path mode's glossy directions and the trace mode's reflections under --glossy. */
#include "light_loop.h"
#include "lobes/phong.h"

#if CLRT_TRANSPORT == CLRT_MODE_PATH
#include "path_step.h"
/* Shadow rays and children leave every vertex. */
#define CLRT_TRANSPORT_SPAWNS 1
CLRT_INLINE float3 transport_step(const Ray* ray, const Hit* hit, __global const Material* materials,
                                  TEXTURE_PARAMS, __global const Light* lights, __global const RenderParams* params,
                                  uint owner, RaySink* sink) {
  return path_step(ray, hit, materials, TEXTURE_ARGS, lights, params, owner, sink);
}
#else
#include "whitted_step.h"
#define CLRT_TRANSPORT_SPAWNS (CLRT_TRANSPORT == CLRT_MODE_TRACE)
CLRT_INLINE float3 transport_step(const Ray* ray, const Hit* hit, __global const Material* materials,
                                  TEXTURE_PARAMS, __global const Light* lights, __global const RenderParams* params,
                                  uint owner, RaySink* sink) {
  return whitted_step(ray, hit, materials, TEXTURE_ARGS, lights, params, CLRT_TRANSPORT_SPAWNS, owner, sink);
}
#endif

#endif
