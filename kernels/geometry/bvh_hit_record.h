/* The nearest hit found so far during a search, and its conversion into the renderer's Hit
 * once the search is over (normals and materials are only worth computing for the winner). */
#ifndef CLRT_GEOMETRY_BVH_HIT_RECORD_H
#define CLRT_GEOMETRY_BVH_HIT_RECORD_H
#include "shared/ray.h"
#include "shared/scene.h"
#include "geometry/instance.h"
#include "geometry/triangle.h"

typedef struct HitRecord {
  float t;
  u32 instance;      /* CLRT_NO_HIT while nothing was hit */
  u32 triangle;      /* absolute index into the triangle table (meshes only) */
  float u, v;        /* barycentrics of the hit triangle */
  float3 object_normal; /* canonical shapes: outward normal in object space */
} HitRecord;

inline HitRecord hit_record_none(float tmax) {
  HitRecord r;
  r.t = tmax;
  r.instance = CLRT_NO_HIT;
  r.triangle = 0;
  r.u = r.v = 0.0f;
  r.object_normal = (float3)(0.0f);
  return r;
}

inline float3 bvh_float3(f4 v) { return (float3)(v.x, v.y, v.z); }

/* Object-space normal n of instance `inst` in world space; `fallback` when n cannot be
 * normalised (degenerate triangle or interpolated normals that cancel out). */
inline float3 bvh_world_normal(__global const Instance* inst, float3 n, float3 fallback) {
  return dot(n, n) > 0.0f ? instance_normal_to_world(inst, n) : fallback;
}

inline void hit_record_resolve(const HitRecord* r, __global const Instance* instances,
                               __global const Mesh* meshes, __global const Triangle* triangles,
                               __global const TriangleNormals* triangle_normals,
                               __global const u32* triangle_materials, Hit* hit) {
  hit->instance = r->instance;
  hit->pad = 0u;
  if (r->instance == CLRT_NO_HIT) {
    hit->primitive = 0u;
    hit->material = 0u;
    hit->geometric_normal = (float4)(0.0f, 0.0f, 0.0f, r->t);
    hit->shading_normal = (float4)(0.0f);
    return;
  }
  __global const Instance* inst = instances + r->instance;
  float3 geometric, shading;
  if (inst->shape != CLRT_SHAPE_MESH) {
    geometric = shading = bvh_world_normal(inst, r->object_normal, (float3)(0.0f, 1.0f, 0.0f));
    hit->primitive = 0u;
    hit->material = inst->material;
  } else {
    __global const Mesh* mesh = meshes + inst->mesh;
    const Triangle tri = triangles[r->triangle];
    const float3 v0 = bvh_float3(tri.v0), v1 = bvh_float3(tri.v1), v2 = bvh_float3(tri.v2);
    geometric = bvh_world_normal(inst, triangle_normal(v0, v1, v2), (float3)(0.0f, 1.0f, 0.0f));
    shading = geometric;
    if (mesh->has_normals) {
      const TriangleNormals n = triangle_normals[r->triangle];
      const float3 interpolated = (1.0f - r->u - r->v) * bvh_float3(n.n0) +
                                  r->u * bvh_float3(n.n1) + r->v * bvh_float3(n.n2);
      shading = bvh_world_normal(inst, interpolated, geometric);
    }
    hit->primitive = r->triangle - mesh->first_triangle;
    hit->material = inst->material == CLRT_MATERIAL_PER_TRIANGLE
                        ? triangle_materials[r->triangle] : inst->material;
  }
  hit->geometric_normal = (float4)(geometric, r->t);
  hit->shading_normal = (float4)(shading, 0.0f);
}

#endif
