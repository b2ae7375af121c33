/* The shadow stage as a device function, shared by the shadow kernel and the megakernel. */
#ifndef CLRT_RENDER_SHADOW_TEST_H
#define CLRT_RENDER_SHADOW_TEST_H

#include "common.h"
#include "geometry/scene_intersect.h"

/* The ray's contribution when nothing lies between epsilon and the light (origin.w), else 0. */
CLRT_INLINE float4 shadow_visible(SCENE_PARAMS, float epsilon, const ShadowRay* s) {
  const bool blocked = scene_any_hit(SCENE_ARGS, xyz(s->origin), xyz(s->dir), s->time, epsilon,
                                     s->origin.w);
  return blocked ? (float4)(0.0f) : s->contribution;
}

#endif
