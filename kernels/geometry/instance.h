/* Moving rays into an instance's object space and its normals back to world space. */
#ifndef CLRT_GEOMETRY_INSTANCE_H
#define CLRT_GEOMETRY_INSTANCE_H

#include "math/exact.h"

#include "shared/scene.h"

/* A world point or vector (w = 1 or 0) mapped by the rows of M^-1. */
CLRT_INLINE float3 transform_to_object(__global const f4* rows, float4 p) {
  return (float3)(dot4(rows[0], p), dot4(rows[1], p), dot4(rows[2], p));
}

/* A world point mapped by M^-1 (rows of inst->world_to_object). */
CLRT_INLINE float3 instance_point_to_object(__global const Instance* inst, float3 p) {
  return transform_to_object(inst->world_to_object, (float4)(p, 1.0f));
}

/* The world ray mapped by the rows of M^-1. The direction is not normalised, so a t found in
 * object space is the world t. */
CLRT_INLINE void ray_to_object(__global const f4* rows, float3 o, float3 d, float3* object_o,
                          float3* object_d) {
  *object_o = transform_to_object(rows, (float4)(o, 1.0f));
  *object_d = transform_to_object(rows, (float4)(d, 0.0f));
}

CLRT_INLINE void instance_ray_to_object(__global const Instance* inst, float3 o, float3 d,
                                   float3* object_o, float3* object_d) {
  ray_to_object(inst->world_to_object, o, d, object_o, object_d);
}

/* An object-space normal mapped by (M^-1)^T and normalised. */
CLRT_INLINE float3 instance_normal_to_world(__global const Instance* inst, float3 n) {
  const float4 v = (float4)(n, 0.0f);
  return normalize3((float3)(dot4(inst->normal_to_world[0], v), dot4(inst->normal_to_world[1], v),
                             dot4(inst->normal_to_world[2], v)));
}

#endif
