/* The leaves' packets (kernels/shared/bvh.h): triangles and world-space spheres, four at a time,
 * one per float4 lane. */
#ifndef CLRT_GEOMETRY_BVH_PACKETS_H
#define CLRT_GEOMETRY_BVH_PACKETS_H

#include "math/exact.h"
#include "shared/bvh.h"
#include "shared/ray.h"
#include "geometry/bvh_hit_record.h"
#include "geometry/bvh_ray.h"
#include "geometry/triangle.h"

/* The lane of the nearest hit among `hit` (at least one), the first on a tie so that the result
 * depends on nothing but the data; *t_nearest is its t. */
CLRT_INLINE int bvh_nearest_lane(int4 hit, float4 t, float* t_nearest) {
  const float4 masked = select((float4)(INFINITY), t, hit);
  const float nearest = min(min(masked.x, masked.y), min(masked.z, masked.w));
  const int4 at = isequal(masked, (float4)(nearest)) & hit;
  *t_nearest = nearest;
  return at.x ? 0 : (at.y ? 1 : (at.z ? 2 : 3));
}

CLRT_INLINE bool bvh_any_lane(int4 hit) { return (hit.x | hit.y | hit.z | hit.w) != 0; }

/* The triangles of `packet` in the frame of the ray's watertight test. */
CLRT_INLINE Triangle4 bvh_load_triangles(__global const BvhTrianglePacket* packet, const TriangleRay* r) {
  Triangle4 p;
  for (int j = 0; j < 3; ++j) {
    p.x[j] = packet->v[3 * j + r->kx];
    p.y[j] = packet->v[3 * j + r->ky];
    p.z[j] = packet->v[3 * j + r->kz];
  }
  return p;
}

/* The `packets` triangle packets from `block` against the mesh's (object-space) ray; the nearest
 * hit in (tmin, best->t) goes into *best, as a hit of `instance` (CLRT_NO_HIT: of the instance
 * the packets name). `first_found` stops at the first packet with a hit. */
CLRT_INLINE bool bvh_test_triangles(__global const BvhBlock* bvh, int block, u32 packets, u32 instance,
                               const BvhRay* ray, float tmin, bool first_found, HitRecord* best) {
  if (!ray->tri.valid) return false;
  __global const BvhTrianglePacket* packet = (__global const BvhTrianglePacket*)(bvh + block);
  bool found = false;
  for (u32 p = 0; p < packets; ++p, ++packet) {
    const Triangle4 tri = bvh_load_triangles(packet, &ray->tri);
    const Triangle4Hits h = triangle4_test(&ray->tri, &tri, tmin, best->t);
    if (!bvh_any_lane(h.hit)) continue;
    const int k = bvh_nearest_lane(h.hit, h.t, &best->t);
    float det[4], wb[4], wc[4];
    vstore4(h.det, 0, det);
    vstore4(h.wb, 0, wb);
    vstore4(h.wc, 0, wc);
    best->instance = instance != CLRT_NO_HIT ? instance : packet->instance;
    best->packet = block + (int)p * CLRT_BVH_PACKET_BLOCKS;
    best->lane = k;
    best->u = wb[k] / det[k];
    best->v = wc[k] / det[k];
    found = true;
    if (first_found) break;
  }
  return found;
}

/* Where the world ray o + t d meets the spheres of `p` with tmin < t < tmax: the entry, or the
 * exit for a ray that starts inside, as sphere_span and span_hit find it for the unit sphere
 * (the same formulas with the radius put in). */
CLRT_INLINE int4 sphere4_test(__global const BvhSpherePacket* p, float3 o, float3 d, float tmin,
                         float tmax, float4* t) {
  const float4 ox = o.x - p->center_x, oy = o.y - p->center_y, oz = o.z - p->center_z;
  const float4 r2 = p->radius * p->radius;
  const float a = dot3(d, d);
  const float4 b = ox * d.x + oy * d.y + oz * d.z;
  /* r^2 - |l|^2 for l the point of the line nearest the centre keeps its precision when the
   * origin is far from the sphere, unlike b^2 - a c. A zero d gives NaN: a miss. */
  const float4 s = b / a;
  const float4 lx = ox - s * d.x, ly = oy - s * d.y, lz = oz - s * d.z;
  const float4 disc = a * (r2 - (lx * lx + ly * ly + lz * lz));
  const float4 c = ox * ox + oy * oy + oz * oz - r2;
  const float4 q = -(b + copysign(sqrt(disc), b));
  /* q is 0 only for b = 0 and disc = 0: the double root at 0. */
  const int4 double_zero = q == 0.0f;
  const float4 r0 = select(q / a, (float4)(0.0f), double_zero);
  const float4 r1 = select(c / q, (float4)(0.0f), double_zero);
  const float4 t0 = fmin(r0, r1), t1 = fmax(r0, r1);
  *t = select(t1, t0, t0 > tmin);
  const int4 present = as_int4(vload4(0, p->instance)) != (int)CLRT_NO_HIT;
  return present & (disc >= 0.0f) & (*t > tmin) & (*t < tmax);
}

/* The `packets` sphere packets from `block` against the world ray; the nearest hit in
 * (tmin, best->t) goes into *best. `first_found` stops at the first packet with a hit. */
CLRT_INLINE bool bvh_test_spheres(__global const BvhBlock* bvh, int block, u32 packets, float3 o,
                             float3 d, float tmin, bool first_found, HitRecord* best) {
  __global const BvhSpherePacket* packet = (__global const BvhSpherePacket*)(bvh + block);
  bool found = false;
  for (u32 p = 0; p < packets; ++p, ++packet) {
    float4 t;
    const int4 hit = sphere4_test(packet, o, d, tmin, best->t, &t);
    if (!bvh_any_lane(hit)) continue;
    best->instance = packet->instance[bvh_nearest_lane(hit, t, &best->t)];
    found = true;
    if (first_found) break;
  }
  return found;
}

#endif
