/* Moving rays into an instance's object space and its normals back to world space, by the maps
 * of an InstanceFrame (geometry/motion.h): the instance's own, or its pose at the ray's time. */
#ifndef CLRT_GEOMETRY_INSTANCE_H
#define CLRT_GEOMETRY_INSTANCE_H

#include "math/exact.h"
#include "geometry/motion.h"

/* A world point or vector (w = 1 or 0) mapped by the rows of M^-1. */
CLRT_INLINE float3 transform_to_object(const float4* rows, float4 p) {
  return (float3)(dot4(rows[0], p), dot4(rows[1], p), dot4(rows[2], p));
}

/* A world point mapped by M^-1. */
CLRT_INLINE float3 frame_point_to_object(const InstanceFrame* f, float3 p) {
  return transform_to_object(f->to_object, (float4)(p, 1.0f));
}

/* The world ray mapped by the rows of M^-1. The direction is not normalised, so a t found in
 * object space is the world t. */
CLRT_INLINE void ray_to_object(const float4* rows, float3 o, float3 d, float3* object_o,
                               float3* object_d) {
  *object_o = transform_to_object(rows, (float4)(o, 1.0f));
  *object_d = transform_to_object(rows, (float4)(d, 0.0f));
}

/* An object-space normal mapped by (M^-1)^T and normalised. */
CLRT_INLINE float3 frame_normal_to_world(const InstanceFrame* f, float3 n) {
  const float4 v = (float4)(n, 0.0f);
  return normalize3((float3)(dot4(f->normal_to_world[0], v), dot4(f->normal_to_world[1], v),
                             dot4(f->normal_to_world[2], v)));
}

#endif
