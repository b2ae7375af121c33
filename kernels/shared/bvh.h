/* BVH nodes shared by the host builder (src/geometry) and the traversal kernels
 * (kernels/geometry/bvh_*.h). One node table holds the top level over the instances (root at
 * node 0) and every mesh's bottom level (root at Mesh.root_node). */
#ifndef CLRT_SHARED_BVH_H
#define CLRT_SHARED_BVH_H
#include "common.h"

CLRT_SHARED_BEGIN

/* Children per node: 4 or 8. The device tests all of a node's child boxes at once with one
 * float4 or float8 operation per slab, which is how a CPU device gets the SIMD box tests a wide
 * BVH is for. */
#define CLRT_BVH_WIDTH 8

/* One float per child, for one bound of one axis. */
#ifdef __OPENCL_VERSION__
#if CLRT_BVH_WIDTH == 8
typedef float8 BvhLanes;
#else
typedef float4 BvhLanes;
#endif
#else
struct alignas(4 * CLRT_BVH_WIDTH) BvhLanes {
  float lane[CLRT_BVH_WIDTH];
};
#endif

/* Most node levels on a path from a root to a leaf, per BVH level (top and bottom): the builder
 * keeps every tree within it, which bounds the traversal stack. */
#define CLRT_BVH_MAX_DEPTH (CLRT_BVH_WIDTH == 8 ? 10 : 16)

/* Entries a traversal may hold at once: every node visited pushes at most WIDTH children and
 * pops one, for at most MAX_DEPTH nodes on each of the two levels, plus the entry that leads
 * back from a mesh to the top level. */
#define CLRT_BVH_STACK_SIZE (2 * (CLRT_BVH_WIDTH - 1) * CLRT_BVH_MAX_DEPTH + CLRT_BVH_WIDTH + 2)

/* Most items (triangles; instances are always alone) in one leaf. */
#define CLRT_BVH_MAX_LEAF 8

/* A lane with no child: an empty box (min = +inf, max = -inf) that no ray enters. */
#define CLRT_BVH_EMPTY_LANE (-1)

/* The boxes of a node's (up to) WIDTH children stored per axis and bound, so that the device
 * tests them all with one vector operation per slab. */
typedef struct BvhNode {
  BvhLanes min_x, max_x, min_y, max_y, min_z, max_z; /* lane k: child k's box */
  i32 child[CLRT_BVH_WIDTH]; /* >= 0: index of an inner node; < 0: a leaf whose first item is ~child */
  u32 count[CLRT_BVH_WIDTH]; /* leaf: number of items (0 for an empty lane); 0 for inner children */
} BvhNode;
CLRT_CHECK_SIZE(BvhNode, 32 * CLRT_BVH_WIDTH);

CLRT_SHARED_END

#endif
