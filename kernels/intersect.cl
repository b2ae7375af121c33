/* intersect: the closest hit of every ray of the queue.
 * In: rays[0, count). Out: hits[i] for rays[i] (instance CLRT_NO_HIT on a miss). */
#include "render/common.h"
#include "geometry/scene_intersect.h"

__kernel void intersect(SCENE_PARAMS, __global const RenderParams* params,
                        __global const Ray* rays, uint count, __global Hit* hits) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  Hit hit;
  scene_closest_hit(SCENE_ARGS, vload3(0, rays[i].origin), vload3(0, rays[i].dir), rays[i].time,
                    params->epsilon, INFINITY, &hit);
  hits[i] = hit;
}
