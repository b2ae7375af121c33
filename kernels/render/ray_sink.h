/* Where a transport step's shadow and child rays go (render/transport_step.h), one type for both
 * integrators because every kernel file is part of one program:
 *   queue sink (wavefront)  writes them to the ray's slots, flagged for compaction; the shadow
 *                           rays' contributions are added later by accumulate.cl;
 *   stack sink (megakernel) tests a shadow ray at once, adding what it lets through, and pushes
 *                           a child on the work-item's private stack.
 * Each kernel makes one kind with a constant tag, so after inlining the other kind's code is
 * gone. */
#ifndef CLRT_RENDER_RAY_SINK_H
#define CLRT_RENDER_RAY_SINK_H

#include "common.h"
#include "shadow_test.h"

#define CLRT_SINK_QUEUE 0u
#define CLRT_SINK_STACK 1u

/* The two children a ray may have: its reflection (slot 0; a path's next ray) and its
 * refraction (slot 1). */
#define CLRT_SPAWN_REFLECTION 1u
#define CLRT_SPAWN_REFRACTION 2u

typedef struct RaySink {
  uint kind; /* CLRT_SINK_* */
  /* queue sink: this ray's shadow-sample slots and its CLRT_CHILD_SLOTS child slots */
  __global ShadowRay* shadows;
  __global uint* shadow_flags;
  __global Ray* children;
  __global uint* child_flags;
  /* stack sink */
  SceneTables scene;
  float epsilon;
  Ray* stack;
  uint* top;
  uint* counts; /* rays by kind, CLRT_RAY_KINDS */
} RaySink;

/* Designated initialisers leave the other kind's fields zero: nothing is copied uninitialised. */
CLRT_INLINE RaySink queue_sink(__global ShadowRay* shadows, __global uint* shadow_flags,
                                   __global Ray* children, __global uint* child_flags) {
  const RaySink s = {.kind = CLRT_SINK_QUEUE, .shadows = shadows, .shadow_flags = shadow_flags,
                         .children = children, .child_flags = child_flags};
  return s;
}

CLRT_INLINE RaySink stack_sink(SceneTables scene, float epsilon, Ray* stack, uint* top,
                                   uint* counts) {
  const RaySink s = {.kind = CLRT_SINK_STACK, .scene = scene, .epsilon = epsilon,
                         .stack = stack, .top = top, .counts = counts};
  return s;
}

/* Light sample `slot` (Light.first_sample + j) of the ray needs `shadow` tested. */
CLRT_INLINE void sink_shadow(RaySink* sink, uint slot, const ShadowRay* shadow, float3* colour) {
  if (sink->kind == CLRT_SINK_QUEUE) {
    sink->shadows[slot] = *shadow;
    sink->shadow_flags[slot] = 1u;
  } else {
    ++sink->counts[CLRT_RAY_SHADOW];
    *colour += xyz(shadow_visible(SCENE_ARGS_OF(sink->scene), sink->epsilon, shadow));
  }
}

/* `which` is CLRT_SPAWN_REFLECTION or CLRT_SPAWN_REFRACTION. */
CLRT_INLINE void sink_child(RaySink* sink, uint which, const Ray* child) {
  if (sink->kind == CLRT_SINK_QUEUE) {
    const uint slot = which == CLRT_SPAWN_REFLECTION ? 0u : 1u;
    sink->children[slot] = *child;
    sink->child_flags[slot] = 1u;
  } else {
    sink->stack[(*sink->top)++] = *child;
  }
}

#endif
