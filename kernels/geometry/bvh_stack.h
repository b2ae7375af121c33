/* The traversal stack: node and leaf references still to visit, with the distance at which the
 * ray enters each, so that entries behind the nearest hit found meanwhile are skipped. */
#ifndef CLRT_GEOMETRY_BVH_STACK_H
#define CLRT_GEOMETRY_BVH_STACK_H
#include "shared/bvh.h"
#include "geometry/bvh_ray.h"

/* An entry that is no node or leaf: the ray leaves a mesh's bottom level for the top level. */
#define BVH_LEAVE_MESH INT_MIN

typedef struct BvhStack {
  int ref[CLRT_BVH_STACK_SIZE];   /* BvhNode.child encoding, or BVH_LEAVE_MESH */
  u32 count[CLRT_BVH_STACK_SIZE]; /* leaf item count */
  float t[CLRT_BVH_STACK_SIZE];   /* entry distance */
  int size;
} BvhStack;

inline void bvh_push(BvhStack* s, int ref, u32 count, float t) {
  s->ref[s->size] = ref;
  s->count[s->size] = count;
  s->t[s->size] = t;
  ++s->size;
}

/* Starts loading a node that is about to be pushed: traversal is bound by memory latency, and
 * the loads of the nodes pushed now overlap with the work on the nearest child (20% more
 * incoherent rays per second on PoCL). */
inline void bvh_prefetch(__global const BvhNode* node) {
#ifdef __clang__
  /* PoCL's prefetch() does nothing; clang's builtin emits the instruction. */
  for (uint b = 0; b < sizeof(BvhNode); b += 64) __builtin_prefetch((__global const char*)node + b);
#else
  prefetch((__global const char*)node, sizeof(BvhNode));
#endif
}

/* Pushes the children of `node` that the ray enters in [tmin, tmax]. When `ordered`, they go
 * on sorted so that the nearest is popped first: closest-hit searches then find near hits
 * early and skip what lies behind them. */
inline void bvh_push_children(BvhStack* s, __global const BvhNode* nodes, int index,
                              const BvhRay* ray, float tmin, float tmax, bool ordered) {
  __global const BvhNode* node = nodes + index;
  BvhLanes t_enter;
  int mask = bvh_node_test(node, ray, tmin, tmax, &t_enter);
  float t[CLRT_BVH_WIDTH];
  bvh_store_lanes(t_enter, 0, t);
  const int base = s->size;
  while (mask != 0) {
    const int k = 31 - clz(mask & -mask);
    mask &= mask - 1;
    int i = s->size++;
    for (; ordered && i > base && s->t[i - 1] < t[k]; --i) {
      s->ref[i] = s->ref[i - 1];
      s->count[i] = s->count[i - 1];
      s->t[i] = s->t[i - 1];
    }
    if (node->child[k] >= 0) bvh_prefetch(nodes + node->child[k]);
    s->ref[i] = node->child[k];
    s->count[i] = node->count[k];
    s->t[i] = t[k];
  }
}

#endif
