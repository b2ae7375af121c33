/* The nearest hit found so far during a search, and its conversion into the renderer's Hit
 * once the search is over (normals and materials are only worth computing for the winner). */
#ifndef CLRT_GEOMETRY_BVH_HIT_RECORD_H
#define CLRT_GEOMETRY_BVH_HIT_RECORD_H

#include "math/exact.h"
#include "shared/bvh.h"
#include "shared/ray.h"
#include "shared/scene.h"
#include "geometry/instance.h"
#include "geometry/texcoords.h"
#include "geometry/triangle.h"

typedef struct HitRecord {
  float t;
  u32 instance;      /* CLRT_NO_HIT while nothing was hit */
  int packet, lane;  /* meshes: the hit triangle's packet (block) and lane */
  float u, v;        /* barycentrics of the hit triangle */
  float3 object_normal; /* canonical shapes but spheres: outward normal in object space */
} HitRecord;

CLRT_INLINE HitRecord hit_record_none(float tmax) {
  HitRecord r;
  r.t = tmax;
  r.instance = CLRT_NO_HIT;
  r.packet = r.lane = 0;
  r.u = r.v = 0.0f;
  r.object_normal = (float3)(0.0f);
  return r;
}

/* Object-space normal n of an instance in world space, by its frame f; `fallback` when n cannot
 * be normalised (degenerate triangle or interpolated normals that cancel out). */
CLRT_INLINE float3 bvh_world_normal(const InstanceFrame* f, float3 n, float3 fallback) {
  return dot3(n, n) > 0.0f ? frame_normal_to_world(f, n) : fallback;
}

/* Vertex j of lane `lane` of a triangle packet. */
CLRT_INLINE float3 bvh_packet_vertex(__global const BvhTrianglePacket* p, int j, int lane) {
  __global const float* v = (__global const float*)(p->v + 3 * j);
  return (float3)(v[lane], v[4 + lane], v[8 + lane]);
}

/* The hit of the world ray o + t d at `time` that *r records, as the renderer's Hit. A sphere's object-space
 * normal is its hit point in object space (the sphere tests in world space leave none); a
 * triangle's vertices come from its packet, which the search has just read, rather than from
 * the triangle table. */
CLRT_INLINE void hit_record_resolve(const HitRecord* r, float3 o, float3 d, float time,
                               __global const Instance* instances,
                               __global const InstanceMotion* motions,
                               __global const Mesh* meshes, __global const BvhBlock* bvh,
                               __global const TriangleNormals* triangle_normals,
                               __global const TriangleTexcoords* triangle_texcoords,
                               __global const u32* triangle_materials, Hit* hit) {
  hit->instance = r->instance;
  if (r->instance == CLRT_NO_HIT) {
    hit->glow = CLRT_NO_GLOW;
    hit->primitive = 0u;
    hit->material = 0u;
    hit->geometric_normal = (float4)(0.0f, 0.0f, 0.0f, r->t);
    hit->shading_normal = (float4)(0.0f);
    hit->u = hit->v = hit->uv_scale = hit->pad = 0.0f;
    return;
  }
  __global const Instance* inst = instances + r->instance;
  hit->glow = inst->glow;
  const InstanceFrame frame = instance_frame(inst, motions, time);
  float3 geometric, shading, object_normal;
  SurfaceCoords coords;
  if (inst->shape != CLRT_SHAPE_MESH) {
    const float3 p = frame_point_to_object(&frame, o + r->t * d);
    object_normal = inst->shape == CLRT_SHAPE_SPHERE ? p : r->object_normal;
    geometric = shading = bvh_world_normal(&frame, object_normal, (float3)(0.0f, 1.0f, 0.0f));
    coords = shape_coords(inst->shape, inst->cone_r0, inst->cone_r1, p, object_normal);
    hit->primitive = 0u;
    hit->material = inst->material;
  } else {
    __global const Mesh* mesh = meshes + inst->mesh;
    __global const BvhTrianglePacket* packet = (__global const BvhTrianglePacket*)(bvh + r->packet);
    const u32 triangle = packet->triangle[r->lane];
    const float3 v0 = bvh_packet_vertex(packet, 0, r->lane), v1 = bvh_packet_vertex(packet, 1, r->lane),
                 v2 = bvh_packet_vertex(packet, 2, r->lane);
    object_normal = triangle_normal(v0, v1, v2);
    geometric = bvh_world_normal(&frame, object_normal, (float3)(0.0f, 1.0f, 0.0f));
    shading = geometric;
    hit->primitive = triangle - mesh->first_triangle;
    if (mesh->normals != CLRT_NO_NORMALS) {
      __global const float* n = triangle_normals[mesh->normals + hit->primitive].n;
      const float3 interpolated = (1.0f - r->u - r->v) * (float3)(n[0], n[1], n[2]) +
                                  r->u * (float3)(n[3], n[4], n[5]) + r->v * (float3)(n[6], n[7], n[8]);
      shading = bvh_world_normal(&frame, interpolated, geometric);
    }
    coords = triangle_coords(triangle_texcoords,
                             mesh->texcoords == CLRT_NO_TEXCOORDS ? CLRT_NO_TEXCOORDS
                                                                  : mesh->texcoords + hit->primitive,
                             r->u, r->v, v1 - v0, v2 - v0);
    const u32 own = inst->material_rows == CLRT_NO_MATERIAL_ROWS
                        ? CLRT_INSTANCE_MATERIAL : triangle_materials[inst->material_rows + hit->primitive];
    hit->material = own == CLRT_INSTANCE_MATERIAL ? inst->material : own;
  }
  hit->geometric_normal = (float4)(geometric, r->t);
  hit->shading_normal = (float4)(shading, 0.0f);
  hit->u = CLRT_SCENE_TEXTURED ? coords.u : 0.0f;
  hit->v = CLRT_SCENE_TEXTURED ? coords.v : 0.0f;
  hit->uv_scale = CLRT_SCENE_TEXTURED && coords.area > 0.0f && dot3(object_normal, object_normal) > 0.0f
                      ? world_uv_scale(&frame, coords.area, normalize3(object_normal)) : 0.0f;
  hit->pad = 0.0f;
}

#endif
