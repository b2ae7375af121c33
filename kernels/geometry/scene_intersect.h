/* Ray queries against the whole scene: the closest hit and the any-hit (shadow) test.
 *
 * The planes are tested in a loop first (they are unbounded); everything else is found through
 * the two-level BVH of kernels/shared/bvh.h. A top-level leaf is a run of sphere packets
 * (spheres under similarities, tested in world space), a canonical shape (tested through its
 * instance), or a mesh instance, whose leaf continues into its mesh's bottom level with the ray
 * mapped into object space. A mesh placed once and as it is needs no mapping: the top level
 * leads straight into its nodes (and a scene of just that mesh has the mesh's level as its top
 * level). One stack serves both levels: entering a mesh pushes a marker under the mesh's root,
 * and popping the marker brings the world ray back. t is the same on both levels because the
 * mapped direction is not normalised.
 *
 * Closest-hit searches visit a node's children nearest first; any-hit searches take them in
 * lane order, which measured faster for shadow rays than sorting (they stop at any hit). There
 * is no triangle table among the parameters: the packets in the BVH hold the triangles the
 * search tests, and the hit's normal comes from the packet too. */
#ifndef CLRT_GEOMETRY_SCENE_INTERSECT_H
#define CLRT_GEOMETRY_SCENE_INTERSECT_H
#include "shared/bvh.h"
#include "shared/ray.h"
#include "shared/scene.h"
#include "geometry/shapes.h"
#include "geometry/triangle.h"
#include "geometry/instance.h"
#include "geometry/bvh_hit_record.h"
#include "geometry/bvh_packets.h"
#include "geometry/bvh_ray.h"
#include "geometry/bvh_stack.h"

#define SCENE_PARAMS uint instance_count, uint plane_count, __global const Instance* instances, __global const InstanceMotion* motions, __global const Mesh* meshes, __global const TriangleNormals* triangle_normals, __global const TriangleTexcoords* triangle_texcoords, __global const uint* triangle_materials, __global const BvhBlock* bvh
#define SCENE_ARGS instance_count, plane_count, instances, motions, meshes, triangle_normals, triangle_texcoords, triangle_materials, bvh
/* The same tables kept in one value by a function that needs them later (a sink), and passed on
 * from it: SceneTables t = {SCENE_ARGS}; scene_any_hit(SCENE_ARGS_OF(t), ...). */
typedef struct SceneTables {
  uint instance_count, plane_count;
  __global const Instance* instances;
  __global const InstanceMotion* motions;
  __global const Mesh* meshes;
  __global const TriangleNormals* triangle_normals;
  __global const TriangleTexcoords* triangle_texcoords;
  __global const uint* triangle_materials;
  __global const BvhBlock* bvh;
} SceneTables;
#define SCENE_ARGS_OF(t) (t).instance_count, (t).plane_count, (t).instances, (t).motions, (t).meshes, (t).triangle_normals, (t).triangle_texcoords, (t).triangle_materials, (t).bvh

/* Canonical shape instance `index` against the world ray at `time`; updates *best on a hit in
 * (tmin, best->t). */
CLRT_INLINE bool bvh_test_shape(__global const Instance* instances,
                                __global const InstanceMotion* motions, u32 index, float3 o,
                                float3 d, float time, float tmin, HitRecord* best) {
  __global const Instance* inst = instances + index;
  float4 rows[3];
  to_object_rows(inst->motion, inst->world_to_object, motions, time, rows);
  float3 oo, od, n;
  ray_to_object(rows, o, d, &oo, &od);
  if (!intersect_canonical(inst->shape, inst->cone_r0, inst->cone_r1, oo, od, tmin, &best->t, &n))
    return false;
  best->instance = index;
  best->object_normal = n;
  return true;
}

/* The search behind both queries, for the ray from origin.xyz along direction.xyz at time
 * origin.w (which places moving instances): hits in (tmin, best->t) go into *best; `any` stops at
 * the first one. Returns whether anything was hit. The one function a compiler may keep out of
 * line (inlined into every kernel it doubles PoCL's cold build), so the ray crosses the call as
 * float4s, never float3s, and its time rides in the origin's spare lane. */
CLRT_CALLABLE bool scene_search(SCENE_PARAMS, float4 origin, float4 direction, float tmin, bool any,
                                HitRecord* best) {
  const float3 o = origin.xyz, d = direction.xyz;
  const float time = origin.w;
  for (u32 p = 0; p < plane_count; ++p)
    if (bvh_test_shape(instances, motions, p, o, d, time, tmin, best) && any) return true;
  if (instance_count == plane_count) return best->instance != CLRT_NO_HIT;
  const BvhRay world = bvh_ray(o, d);
  BvhRay object;                /* the ray in the object space of mesh_instance */
  const BvhRay* ray = &world;   /* the one the current level uses */
  u32 mesh_instance = CLRT_NO_HIT; /* the instance whose bottom level is being traversed */
  BvhStack stack;
  stack.size = 0;
  BvhEntry e = bvh_entry(0, 0u, -INFINITY);
  for (;;) {
    bool hit = false;
    if (e.ref == BVH_LEAVE_MESH) {
      ray = &world;
      mesh_instance = CLRT_NO_HIT;
    } else if (e.ref >= 0) {
      if (bvh_descend(&stack, bvh, ray, tmin, best->t, !any, &e)) continue;
    } else if (e.count & CLRT_BVH_SPHERE_LEAF) {
      hit = bvh_test_spheres(bvh, ~e.ref, e.count & ~CLRT_BVH_SPHERE_LEAF, o, d, tmin, any, best);
    } else if (e.count & CLRT_BVH_INSTANCE_LEAF) {
      hit = bvh_test_shape(instances, motions, ~e.ref, o, d, time, tmin, best);
    } else if (e.count & CLRT_BVH_MESH_LEAF) {
      __global const BvhMeshInstancePacket* entry =
          (__global const BvhMeshInstancePacket*)(bvh + ~e.ref);
      float4 rows[3];
      to_object_rows(entry->motion, entry->world_to_object, motions, time, rows);
      float3 oo, od;
      ray_to_object(rows, o, d, &oo, &od);
      object = bvh_ray(oo, od);
      ray = &object;
      mesh_instance = entry->instance;
      bvh_push(&stack, bvh_entry(BVH_LEAVE_MESH, 0u, -INFINITY));
      e = bvh_entry((int)entry->root, 0u, e.t);
      continue;
    } else {
      hit = bvh_test_triangles(bvh, ~e.ref, e.count, mesh_instance, ray, tmin, any, best);
    }
    if (hit && any) return true;
    if (!bvh_pop(&stack, best->t, &e)) break;
  }
  return best->instance != CLRT_NO_HIT;
}

/* Closest hit with tmin < t < tmax of the ray at `time`. Fills *hit completely: geometric_normal (world, unit,
 * outward/CCW front as the surface defines it, NOT flipped towards the ray) with .w = t,
 * shading_normal (world, unit: interpolated vertex normal for meshes with normals, else the
 * geometric normal), instance, primitive (triangle index within its mesh, else 0), material
 * (resolved: per-triangle for the loose-triangle mesh). On a miss sets hit->instance =
 * CLRT_NO_HIT and returns false. */
CLRT_INLINE bool scene_closest_hit(SCENE_PARAMS, float3 o, float3 d, float time, float tmin,
                                   float tmax, Hit* hit) {
  HitRecord best = hit_record_none(tmax);
  const bool found =
      scene_search(SCENE_ARGS, (float4)(o, time), (float4)(d, 0.0f), tmin, false, &best);
  hit_record_resolve(&best, o, d, time, instances, motions, meshes, bvh, triangle_normals, triangle_texcoords, triangle_materials, hit);
  return found;
}

/* Any hit with tmin <= t < tmax of the ray at `time` (early exit). */
CLRT_INLINE bool scene_any_hit(SCENE_PARAMS, float3 o, float3 d, float time, float tmin,
                               float tmax) {
  HitRecord best = hit_record_none(tmax);
  /* The shape routines accept t > tmin; the next float below tmin makes that t >= tmin. */
  return scene_search(SCENE_ARGS, (float4)(o, time), (float4)(d, 0.0f),
                      nextafter(tmin, -INFINITY), true, &best);
}

#endif
