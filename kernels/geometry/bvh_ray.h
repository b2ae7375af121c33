/* A ray prepared for BVH box tests and triangle packets, and the test of all of a node's child
 * boxes at once. */
#ifndef CLRT_GEOMETRY_BVH_RAY_H
#define CLRT_GEOMETRY_BVH_RAY_H
#include "shared/bvh.h"
#include "geometry/triangle.h"

typedef struct BvhRay {
  float3 o, d;   /* as the shape routines take them */
  float3 inv_d;  /* 1 / d, with zero components replaced by a tiny number of the same sign */
  /* Per axis, the node bounds (bvh_node_test) where the ray enters and leaves the slab: the min
   * side first, unless the ray runs towards -axis. */
  int near_x, far_x, near_y, far_y, near_z, far_z;
  TriangleRay tri; /* the watertight test's set-up, done once per ray */
} BvhRay;

/* The lanes' vector helpers for the node width. A lane mask has bit 8 k set for lane k: the
 * comparison narrowed to bytes and read as one integer, which is a couple of instructions where
 * or-ing bits across the vector took ten. */
#if CLRT_BVH_WIDTH == 8
#define bvh_store_lanes vstore8
typedef ulong BvhMask;
CLRT_INLINE BvhMask bvh_lane_mask(int8 b) { return as_ulong(convert_uchar8(b)) & 0x0101010101010101ul; }
#define bvh_load_lanes(p) vload8(0, p)
#else
#define bvh_store_lanes vstore4
typedef uint BvhMask;
CLRT_INLINE BvhMask bvh_lane_mask(int4 b) { return as_uint(convert_uchar4(b)) & 0x01010101u; }
#define bvh_load_lanes(p) vload4(0, p)
#endif

/* The lowest lane of a non-zero mask. */
CLRT_INLINE int bvh_first_lane(BvhMask m) {
  return (int)(8 * sizeof(BvhMask) - 1 - clz(m & (~m + 1))) >> 3;
}

CLRT_INLINE BvhRay bvh_ray(float3 o, float3 d) {
  BvhRay r;
  r.o = o;
  r.d = d;
  /* With an exact zero, a slab plane through the origin would give 0 * inf = NaN. */
  const float3 tiny = copysign((float3)(1e-30f), d);
  r.inv_d = 1.0f / select(d, tiny, isless(fabs(d), (float3)(1e-30f)));
  const int neg_x = r.inv_d.x < 0.0f, neg_y = r.inv_d.y < 0.0f, neg_z = r.inv_d.z < 0.0f;
  r.near_x = neg_x;
  r.far_x = 1 - neg_x;
  r.near_y = 2 + neg_y;
  r.far_y = 3 - neg_y;
  r.near_z = 4 + neg_z;
  r.far_z = 5 - neg_z;
  r.tri = triangle_ray(o, d);
  return r;
}

/* Slightly more than 1: the far distance is scaled up by a few ulps so that rounding in the
 * box test cannot cull a box whose primitive the exact test would hit. */
#define BVH_FAR_SCALE 1.0000004f

/* Lane k set when the ray enters child box k within [tmin, tmax]; *t_enter holds the entry
 * distances. The near side of each slab is chosen by the ray's sign, so the empty lanes
 * (min = +inf, max = -inf) give near = +inf, far = -inf and are never entered. */
CLRT_INLINE BvhMask bvh_node_test(__global const BvhNode* node, const BvhRay* r, float tmin, float tmax,
                         BvhLanes* t_enter) {
  /* min_x, max_x, min_y, max_y, min_z, max_z are consecutive members of one type. */
  __global const BvhLanes* bounds = &node->min_x;
  const BvhLanes near_x = (bounds[r->near_x] - r->o.x) * r->inv_d.x;
  const BvhLanes far_x = (bounds[r->far_x] - r->o.x) * r->inv_d.x;
  const BvhLanes near_y = (bounds[r->near_y] - r->o.y) * r->inv_d.y;
  const BvhLanes far_y = (bounds[r->far_y] - r->o.y) * r->inv_d.y;
  const BvhLanes near_z = (bounds[r->near_z] - r->o.z) * r->inv_d.z;
  const BvhLanes far_z = (bounds[r->far_z] - r->o.z) * r->inv_d.z;
  /* max and min, not fmax and fmin: no operand is NaN (the inverse direction is finite), and
   * they compile to one instruction each instead of a NaN-aware sequence. */
  const BvhLanes t0 = max(max(near_x, near_y), max(near_z, (BvhLanes)(tmin)));
  const BvhLanes t1 = min(min(far_x, far_y), min(far_z, (BvhLanes)(tmax))) * BVH_FAR_SCALE;
  *t_enter = t0;
  return bvh_lane_mask(islessequal(t0, t1));
}

#endif
