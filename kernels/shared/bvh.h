/* BVH nodes shared by the host builder (src/geometry) and the traversal kernels. */
#ifndef CLRT_SHARED_BVH_H
#define CLRT_SHARED_BVH_H
#include "common.h"

CLRT_SHARED_BEGIN

/* A 4-wide node: the boxes of its (up to) four children stored per axis, so the device tests
 * all four with float4 operations. */
typedef struct BvhNode {
  f4 min_x, max_x, min_y, max_y, min_z, max_z; /* lane k: child k's box */
  i32 child[4];  /* >= 0: index of an inner node; < 0: a leaf whose first item is ~child */
  u32 count[4];  /* leaf: number of items; 0 for inner children and empty lanes */
} BvhNode;
CLRT_CHECK_SIZE(BvhNode, 128);

CLRT_SHARED_END

#endif
