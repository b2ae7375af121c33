/* Ray queries against the whole scene: the closest hit and the any-hit (shadow) test.
 * FIRST VERSION: brute force over every instance and every triangle of every mesh, so that
 * the renderer can run while the two-level BVH is being written; it will replace this. */
#ifndef CLRT_GEOMETRY_SCENE_INTERSECT_H
#define CLRT_GEOMETRY_SCENE_INTERSECT_H
#include "shared/bvh.h"
#include "shared/ray.h"
#include "shared/scene.h"
#include "geometry/shapes.h"
#include "geometry/triangle.h"
#include "geometry/instance.h"
#include "geometry/bvh_hit_record.h"

#define SCENE_PARAMS u32 instance_count, u32 plane_count, __global const Instance* instances, __global const Mesh* meshes, __global const Triangle* triangles, __global const TriangleNormals* triangle_normals, __global const u32* triangle_materials, __global const BvhNode* nodes
#define SCENE_ARGS instance_count, plane_count, instances, meshes, triangles, triangle_normals, triangle_materials, nodes

/* Updates *best when instance i has a hit with tmin < t < best->t; true when it did. */
inline bool scene_test_instance(SCENE_PARAMS, u32 i, float3 o, float3 d, float tmin,
                                HitRecord* best) {
  __global const Instance* inst = instances + i;
  float3 oo, od;
  instance_ray_to_object(inst, o, d, &oo, &od);
  bool found = false;
  if (inst->shape != CLRT_SHAPE_MESH) {
    float3 n;
    if (intersect_canonical(inst->shape, inst->cone_r0, inst->cone_r1, oo, od, tmin, &best->t, &n)) {
      best->instance = i;
      best->object_normal = n;
      found = true;
    }
    return found;
  }
  const Mesh mesh = meshes[inst->mesh];
  for (u32 k = mesh.first_triangle; k < mesh.first_triangle + mesh.triangle_count; ++k) {
    const Triangle tri = triangles[k];
    float u, v;
    if (intersect_triangle(bvh_float3(tri.v0), bvh_float3(tri.v1), bvh_float3(tri.v2), oo, od,
                           tmin, &best->t, &u, &v)) {
      best->instance = i;
      best->triangle = k;
      best->u = u;
      best->v = v;
      found = true;
    }
  }
  return found;
}

/* Closest hit with tmin < t < tmax. Fills *hit completely: geometric_normal (world, unit,
 * outward/CCW front as the surface defines it, NOT flipped towards the ray) with .w = t,
 * shading_normal (world, unit: interpolated vertex normal for meshes with normals, else the
 * geometric normal), instance, primitive (triangle index within its mesh, else 0), material
 * (resolved: per-triangle for the loose-triangle mesh). On a miss sets hit->instance =
 * CLRT_NO_HIT and returns false. */
inline bool scene_closest_hit(SCENE_PARAMS, float3 o, float3 d, float tmin, float tmax, Hit* hit) {
  HitRecord best = hit_record_none(tmax);
  for (u32 i = 0; i < instance_count; ++i) scene_test_instance(SCENE_ARGS, i, o, d, tmin, &best);
  hit_record_resolve(&best, instances, meshes, triangles, triangle_normals, triangle_materials, hit);
  return best.instance != CLRT_NO_HIT;
}

/* Any hit with tmin <= t < tmax (early exit). */
inline bool scene_any_hit(SCENE_PARAMS, float3 o, float3 d, float tmin, float tmax) {
  /* The shape routines accept t > tmin; the next float below tmin makes that t >= tmin. */
  const float below = nextafter(tmin, -INFINITY);
  HitRecord best = hit_record_none(tmax);
  for (u32 i = 0; i < instance_count; ++i)
    if (scene_test_instance(SCENE_ARGS, i, o, d, below, &best)) return true;
  return false;
}

#endif
