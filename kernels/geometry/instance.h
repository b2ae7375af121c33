/* Moving rays into an instance's object space and its normals back to world space. */
#ifndef CLRT_GEOMETRY_INSTANCE_H
#define CLRT_GEOMETRY_INSTANCE_H

#include "shared/scene.h"

/* The world ray mapped by M^-1 (rows of inst->world_to_object). The direction is not
 * normalised, so a t found in object space is the world t. */
inline void instance_ray_to_object(__global const Instance* inst, float3 o, float3 d,
                                   float3* object_o, float3* object_d) {
  const float4 point = (float4)(o, 1.0f), vector = (float4)(d, 0.0f);
  *object_o = (float3)(dot(inst->world_to_object[0], point), dot(inst->world_to_object[1], point),
                       dot(inst->world_to_object[2], point));
  *object_d = (float3)(dot(inst->world_to_object[0], vector),
                       dot(inst->world_to_object[1], vector),
                       dot(inst->world_to_object[2], vector));
}

/* An object-space normal mapped by (M^-1)^T and normalised. */
inline float3 instance_normal_to_world(__global const Instance* inst, float3 n) {
  const float4 v = (float4)(n, 0.0f);
  return normalize((float3)(dot(inst->normal_to_world[0], v), dot(inst->normal_to_world[1], v),
                            dot(inst->normal_to_world[2], v)));
}

#endif
