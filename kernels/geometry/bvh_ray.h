/* A ray prepared for BVH box tests, and the test of all of a node's child boxes at once. */
#ifndef CLRT_GEOMETRY_BVH_RAY_H
#define CLRT_GEOMETRY_BVH_RAY_H
#include "shared/bvh.h"

typedef struct BvhRay {
  float3 o, d;   /* as the shape and triangle routines take them */
  float3 inv_d;  /* 1 / d, with zero components replaced by a tiny number of the same sign */
  int neg_x, neg_y, neg_z; /* the ray runs towards -axis: it enters a slab at its max side */
} BvhRay;

/* One bit per lane, and the lanes' vector helpers, for the node width. */
#if CLRT_BVH_WIDTH == 8
#define BVH_LANE_BITS ((int8)(1, 2, 4, 8, 16, 32, 64, 128))
#define bvh_store_lanes vstore8
inline int bvh_or_lanes(int8 b) {
  const int4 h = b.lo | b.hi;
  return h.x | h.y | h.z | h.w;
}
#else
#define BVH_LANE_BITS ((int4)(1, 2, 4, 8))
#define bvh_store_lanes vstore4
inline int bvh_or_lanes(int4 b) { return b.x | b.y | b.z | b.w; }
#endif

inline BvhRay bvh_ray(float3 o, float3 d) {
  BvhRay r;
  r.o = o;
  r.d = d;
  /* With an exact zero, a slab plane through the origin would give 0 * inf = NaN. */
  const float3 tiny = copysign((float3)(1e-30f), d);
  r.inv_d = 1.0f / select(d, tiny, isless(fabs(d), (float3)(1e-30f)));
  r.neg_x = r.inv_d.x < 0.0f;
  r.neg_y = r.inv_d.y < 0.0f;
  r.neg_z = r.inv_d.z < 0.0f;
  return r;
}

/* Slightly more than 1: the far distance is scaled up by a few ulps so that rounding in the
 * box test cannot cull a box whose primitive the exact test would hit. */
#define BVH_FAR_SCALE 1.0000004f

/* Bit k set when the ray enters child box k within [tmin, tmax]; *t_enter holds the entry
 * distances. The near side of each slab is chosen by the ray's sign, so the empty lanes
 * (min = +inf, max = -inf) give near = +inf, far = -inf and are never entered. */
inline int bvh_node_test(__global const BvhNode* node, const BvhRay* r, float tmin, float tmax,
                         BvhLanes* t_enter) {
  const BvhLanes near_x = ((r->neg_x ? node->max_x : node->min_x) - r->o.x) * r->inv_d.x;
  const BvhLanes far_x = ((r->neg_x ? node->min_x : node->max_x) - r->o.x) * r->inv_d.x;
  const BvhLanes near_y = ((r->neg_y ? node->max_y : node->min_y) - r->o.y) * r->inv_d.y;
  const BvhLanes far_y = ((r->neg_y ? node->min_y : node->max_y) - r->o.y) * r->inv_d.y;
  const BvhLanes near_z = ((r->neg_z ? node->max_z : node->min_z) - r->o.z) * r->inv_d.z;
  const BvhLanes far_z = ((r->neg_z ? node->min_z : node->max_z) - r->o.z) * r->inv_d.z;
  /* max and min, not fmax and fmin: no operand is NaN (the inverse direction is finite), and
   * they compile to one instruction each instead of a NaN-aware sequence. */
  const BvhLanes t0 = max(max(near_x, near_y), max(near_z, (BvhLanes)(tmin)));
  const BvhLanes t1 = min(min(far_x, far_y), min(far_z, (BvhLanes)(tmax))) * BVH_FAR_SCALE;
  *t_enter = t0;
  return bvh_or_lanes(islessequal(t0, t1) & BVH_LANE_BITS);
}

#endif
