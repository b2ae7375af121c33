/* The traversal stack: node and leaf references still to visit, with the distance at which the
 * ray enters each, so that entries behind the nearest hit found meanwhile are skipped. */
#ifndef CLRT_GEOMETRY_BVH_STACK_H
#define CLRT_GEOMETRY_BVH_STACK_H
#include "shared/bvh.h"
#include "geometry/bvh_ray.h"

/* A reference to visit: BvhNode.child's encoding with its count, or BVH_LEAVE_MESH. */
typedef struct BvhEntry {
  int ref;
  u32 count;
  float t; /* entry distance */
} BvhEntry;

/* An entry that is no node or leaf: the ray leaves a mesh's bottom level for the top level. */
#define BVH_LEAVE_MESH INT_MIN

/* Entries are stored as (ref, count, t, unused) in one int4, which moves with one instruction. */
typedef struct BvhStack {
  int4 entry[CLRT_BVH_STACK_SIZE];
  int size;
} BvhStack;

CLRT_INLINE BvhEntry bvh_entry(int ref, u32 count, float t) {
  BvhEntry e;
  e.ref = ref;
  e.count = count;
  e.t = t;
  return e;
}

CLRT_INLINE int4 bvh_pack(int ref, u32 count, float t) { return (int4)(ref, (int)count, as_int(t), 0); }

CLRT_INLINE BvhEntry bvh_unpack(int4 v) { return bvh_entry(v.x, (u32)v.y, as_float(v.z)); }

CLRT_INLINE void bvh_push(BvhStack* s, BvhEntry e) { s->entry[s->size++] = bvh_pack(e.ref, e.count, e.t); }

/* Pops the next entry the ray enters before t_limit into *e; false when none is left. */
CLRT_INLINE bool bvh_pop(BvhStack* s, float t_limit, BvhEntry* e) {
  while (s->size > 0) {
    const int4 top = s->entry[--s->size];
    if (as_float(top.z) < t_limit) {
      *e = bvh_unpack(top);
      return true;
    }
  }
  return false;
}

/* Starts loading a node that is about to be pushed: traversal is bound by memory latency, and
 * the loads of the nodes pushed now overlap with the work on the nearest child (20% more
 * incoherent rays per second on PoCL). */
CLRT_INLINE void bvh_prefetch(__global const BvhNode* node) {
#ifdef CLRT_CLANG_PREFETCH
  /* PoCL's prefetch() does nothing; Clang's builtin emits the instruction. The host asks for it
   * on PoCL alone (src/device/device_context.cpp): other compilers refuse it. */
  for (uint b = 0; b < sizeof(BvhNode); b += 64) __builtin_prefetch((__global const char*)node + b);
#else
  prefetch((__global const char*)node, sizeof(BvhNode));
#endif
}

CLRT_INLINE __global const BvhNode* bvh_node(__global const BvhBlock* table, int block) {
  return (__global const BvhNode*)(table + block);
}

/* Child k entered at t, as a stack entry; an inner node's loading is started. */
CLRT_INLINE int4 bvh_child(__global const BvhBlock* table, const int* child, const u32* count, int k, float t) {
  if (child[k] >= 0) bvh_prefetch(bvh_node(table, child[k]));
  return bvh_pack(child[k], count[k], t);
}

/* Visits the node of *e: the children the ray enters in [tmin, tmax] are to be visited, and *e
 * becomes the first of them while the others are pushed. When `ordered`, that is the nearest
 * and the others are pushed so that they pop nearest first: closest-hit searches then find
 * near hits early and skip what lies behind them. False when the ray enters no child. */
CLRT_INLINE bool bvh_descend(BvhStack* s, __global const BvhBlock* table, const BvhRay* ray,
                        float tmin, float tmax, bool ordered, BvhEntry* e) {
  __global const BvhNode* node = bvh_node(table, e->ref);
  /* The references are read before the box test, not once it has chosen a lane: their cache
   * line then loads alongside the boxes' instead of after them. */
  int child[CLRT_BVH_WIDTH];
  u32 count[CLRT_BVH_WIDTH];
  bvh_store_lanes(bvh_load_lanes(node->child), 0, child);
  bvh_store_lanes(bvh_load_lanes(node->count), 0, count);
  BvhLanes t_enter;
  BvhMask mask = bvh_node_test(node, ray, tmin, tmax, &t_enter);
  if (mask == 0) return false;
  float t[CLRT_BVH_WIDTH];
  bvh_store_lanes(t_enter, 0, t);
  int k = bvh_first_lane(mask);
  mask &= mask - 1;
  if (mask == 0) {
    *e = bvh_entry(child[k], count[k], t[k]);
    return true;
  }
  /* Two or more: the first goes on the stack, the others are sorted in above it. */
  const int base = s->size;
  s->entry[s->size++] = bvh_child(table, child, count, k, t[k]);
  do {
    k = bvh_first_lane(mask);
    mask &= mask - 1;
    const int4 entry = bvh_child(table, child, count, k, t[k]);
    int i = s->size++;
    for (; ordered && i > base && as_float(s->entry[i - 1].z) < t[k]; --i) s->entry[i] = s->entry[i - 1];
    s->entry[i] = entry;
  } while (mask != 0);
  *e = bvh_unpack(s->entry[--s->size]);
  return true;
}

#endif
