/* The BVH table shared by the host builder (src/geometry) and the traversal kernels
 * (kernels/geometry/bvh_*.h): an array of node-sized slots, addressed in 64-byte blocks (one
 * cache line each). It holds wide nodes, each filling one slot, and the leaves' packets
 * (triangles in the bottom levels; spheres and mesh instances in the top level), each spanning
 * whole blocks of slots set aside for them. References are block indices. One table holds the
 * top level over the instances (root at block 0) and every mesh's bottom level (root at
 * Mesh.root_node; for a scene of one mesh placed as it is, the mesh's level is the top level). */
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

/* The table's unit of address. */
typedef struct BvhBlock {
  f4 part[4];
} BvhBlock;
CLRT_CHECK_SIZE(BvhBlock, 64);

/* Most node levels on a path from a root to a leaf, per BVH level (top and bottom): the builder
 * keeps every tree within it, which bounds the traversal stack. */
#define CLRT_BVH_MAX_DEPTH (CLRT_BVH_WIDTH == 8 ? 10 : 16)

/* Entries a traversal may hold at once: every node visited pushes at most WIDTH children and
 * pops one, for at most MAX_DEPTH nodes on each of the two levels, plus the entry that leads
 * back from a mesh to the top level. */
#define CLRT_BVH_STACK_SIZE (2 * (CLRT_BVH_WIDTH - 1) * CLRT_BVH_MAX_DEPTH + CLRT_BVH_WIDTH + 2)

/* Triangles or spheres per packet: the device tests a packet's primitives at once, one per
 * float4 lane. */
#define CLRT_BVH_PACKET 4

/* Most triangles in one bottom-level leaf and spheres in one top-level leaf (in consecutive
 * packets); any other top-level leaf holds one instance. Spheres are cheaper to test than
 * triangles, and overlapping ones (shells-5) ran 10% faster with the larger leaves. */
#define CLRT_BVH_MAX_TRIANGLES 8
#define CLRT_BVH_MAX_SPHERES 16

/* A lane with no child: an empty box (min = +inf, max = -inf) that no ray enters. */
#define CLRT_BVH_EMPTY_LANE (-1)

/* BvhNode.count of a leaf: the number of triangle packets at block ~child, or one of these. */
#define CLRT_BVH_INSTANCE_LEAF 0x80000000u /* ~child is an instance (not a mesh) */
#define CLRT_BVH_SPHERE_LEAF 0x40000000u   /* | n: n sphere packets at block ~child */
#define CLRT_BVH_MESH_LEAF 0x20000000u     /* a mesh instance's packet at block ~child */

/* The boxes of a node's (up to) WIDTH children stored per axis and bound, so that the device
 * tests them all with one vector operation per slab. */
typedef struct BvhNode {
  BvhLanes min_x, max_x, min_y, max_y, min_z, max_z; /* lane k: child k's box */
  i32 child[CLRT_BVH_WIDTH]; /* >= 0: block of an inner node; < 0: a leaf (see count) */
  u32 count[CLRT_BVH_WIDTH]; /* leaf: what ~child is; 0: inner or empty lane */
} BvhNode;
CLRT_CHECK_SIZE(BvhNode, 32 * CLRT_BVH_WIDTH);

/* CLRT_BVH_PACKET triangles of one bottom-level leaf, lane k being triangle k. */
typedef struct BvhTrianglePacket {
  f4 v[9];          /* component a (x, y, z = 0, 1, 2) of vertex j: v[3 j + a] */
  u32 triangle[4];  /* index into the triangle table; CLRT_NO_HIT for an empty lane, whose
                     * vertices are all 0: a degenerate triangle that no ray hits */
  /* The mesh's only instance when its transform is the identity: the top level then leads
   * straight into the mesh's nodes, so no instance leaf says which one was hit. Else
   * CLRT_NO_HIT. */
  u32 instance;
  u32 pad[7];
} BvhTrianglePacket;
CLRT_CHECK_SIZE(BvhTrianglePacket, 192);

/* CLRT_BVH_PACKET spheres of one top-level leaf, lane k being sphere k: instances of the unit
 * sphere whose transform is a similarity, tested in world space (no instance to load, no ray
 * to transform). An empty lane has radius 0 and instance CLRT_NO_HIT. */
typedef struct BvhSpherePacket {
  f4 center_x, center_y, center_z, radius;
  u32 instance[4];
  f4 pad[3];
} BvhSpherePacket;
CLRT_CHECK_SIZE(BvhSpherePacket, 128);

/* A top-level leaf of one mesh instance: all that entering its mesh takes, in one block (the
 * instance and mesh records would be three cache lines). */
typedef struct BvhMeshInstancePacket {
  f4 world_to_object[3]; /* as Instance.world_to_object */
  u32 root;              /* block of the mesh's bottom-level root */
  u32 instance;          /* index into the instance table */
  u32 motion;            /* as Instance.motion: when moving, M^-1 comes from the motion table */
  u32 pad;
} BvhMeshInstancePacket;
CLRT_CHECK_SIZE(BvhMeshInstancePacket, 64);

/* Blocks per record (their sizes are checked above). */
#define CLRT_BVH_NODE_BLOCKS (CLRT_BVH_WIDTH / 2)
#define CLRT_BVH_PACKET_BLOCKS 3
#define CLRT_BVH_SPHERE_BLOCKS 2
#define CLRT_BVH_MESH_INSTANCE_BLOCKS 1

CLRT_SHARED_END

#endif
