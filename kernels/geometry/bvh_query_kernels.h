/* Kernels that run scene_closest_hit and scene_any_hit over a plain array of rays, for the
 * tests (tests/geometry) and the benchmark (tools/bench/scene); the renderer has its own stages.
 * Ray i is rays[2i] = origin with w = tmin, rays[2i + 1] = direction with w = tmax. The
 * SCENE_PARAMS come first (DeviceGeometry::bind), then rays, count and the results. Moving
 * instances are taken at time 0, where the shutter opens by default. */
#ifndef CLRT_GEOMETRY_BVH_QUERY_KERNELS_H
#define CLRT_GEOMETRY_BVH_QUERY_KERNELS_H
#include "geometry/scene_intersect.h"

__kernel void bvh_closest_hits(SCENE_PARAMS, __global const float4* rays, uint count,
                               __global Hit* hits) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float4 o = rays[2 * i], d = rays[2 * i + 1];
  Hit hit;
  scene_closest_hit(SCENE_ARGS, o.xyz, d.xyz, 0.0f, o.w, d.w, &hit);
  hits[i] = hit;
}

/* results[i] = 1 when ray i has a hit with tmin <= t < tmax, else 0. */
__kernel void bvh_any_hits(SCENE_PARAMS, __global const float4* rays, uint count,
                           __global int* results) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float4 o = rays[2 * i], d = rays[2 * i + 1];
  results[i] = scene_any_hit(SCENE_ARGS, o.xyz, d.xyz, 0.0f, o.w, d.w) ? 1 : 0;
}

#endif
