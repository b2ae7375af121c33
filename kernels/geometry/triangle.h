/* Ray-triangle intersection: the watertight test of Woop, Benthin and Wald (JCGT 2013).
 *
 * Why not Moller-Trumbore: it measures each triangle's edges from that triangle's own first
 * vertex, so the two triangles sharing an edge round differently and a ray through the edge
 * can miss both; in closed meshes those cracks show up as speckles, worst for refraction and
 * shadow rays that hit edges at grazing angles. Here the ray is sheared to run along +z and
 * every edge function depends only on the ray and the edge's two vertices, evaluated in the
 * same way by both triangles (with contraction into fma off, so the two results are exact
 * negatives): a ray through a shared edge or vertex hits at least one of the triangles.
 *
 * The shear depends only on the ray, so it is set up once per ray (TriangleRay), and the test
 * runs on four triangles at once, one per float4 lane: the BVH's leaves store their triangles
 * in such packets. The single-triangle test is the same arithmetic in every lane. */
#ifndef CLRT_GEOMETRY_TRIANGLE_H
#define CLRT_GEOMETRY_TRIANGLE_H

#include "math/exact.h"

/* Component k (0, 1 or 2) of v. */
CLRT_INLINE float triangle_component(float3 v, int k) {
  return k == 0 ? v.x : (k == 1 ? v.y : v.z);
}

/* The ray in the frame where it runs along +z: axes kx, ky, kz of world space become x, y, z
 * (kz the dominant axis of d; x and y swapped for a negative d.z, which keeps the winding), and
 * p maps to (p.x - shear.x p.z, p.y - shear.y p.z, shear.z p.z) relative to the origin. */
typedef struct TriangleRay {
  int kx, ky, kz;
  float3 o;     /* the origin's components kx, ky, kz */
  float3 shear; /* d[kx] / d[kz], d[ky] / d[kz], 1 / d[kz] */
  bool valid;   /* false for a zero direction, which hits nothing */
} TriangleRay;

CLRT_INLINE TriangleRay triangle_ray(float3 o, float3 d) {
  TriangleRay r;
  const float3 ad = fabs(d);
  r.kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
  r.kx = r.kz == 2 ? 0 : r.kz + 1;
  r.ky = r.kx == 2 ? 0 : r.kx + 1;
  const float dz = triangle_component(d, r.kz);
  if (dz < 0.0f) {
    const int swap = r.kx;
    r.kx = r.ky;
    r.ky = swap;
  }
  r.valid = dz != 0.0f;
  /* One vector division, exactly the three divisions. */
  r.shear = (float3)(triangle_component(d, r.kx), triangle_component(d, r.ky), 1.0f) / dz;
  r.o = (float3)(triangle_component(o, r.kx), triangle_component(o, r.ky), triangle_component(o, r.kz));
  return r;
}

/* Four triangles, lane k being triangle k: vertex j's components along the ray's kx, ky and kz
 * axes. */
typedef struct Triangle4 {
  float4 x[3], y[3], z[3];
} Triangle4;

/* What the test found per lane; the barycentrics of a lane are wb / det and wc / det. */
typedef struct Triangle4Hits {
  int4 hit;  /* -1 where the triangle is hit with tmin < t < tmax */
  float4 t, det, wb, wc;
} Triangle4Hits;

/* Watertight test of the four triangles; both faces hit. A ray through an edge or vertex (an
 * edge function exactly 0) hits; a degenerate triangle never does. */
CLRT_INLINE Triangle4Hits triangle4_test(const TriangleRay* r, const Triangle4* p, float tmin, float tmax) {
#pragma OPENCL FP_CONTRACT OFF
  float4 x[3], y[3], z[3];
  for (int j = 0; j < 3; ++j) {
    const float4 pz = p->z[j] - r->o.z;
    x[j] = (p->x[j] - r->o.x) - r->shear.x * pz;
    y[j] = (p->y[j] - r->o.y) - r->shear.y * pz;
    z[j] = r->shear.z * pz;
  }
  /* Twice the signed areas seen along the ray, each opposite one vertex: its weight. */
  const float4 wa = x[2] * y[1] - y[2] * x[1];
  const float4 wb = x[0] * y[2] - y[0] * x[2];
  const float4 wc = x[1] * y[0] - y[1] * x[0];
  const int4 outside = (wa < 0.0f | wb < 0.0f | wc < 0.0f) & (wa > 0.0f | wb > 0.0f | wc > 0.0f);
  Triangle4Hits h;
  h.det = wa + wb + wc;
  h.t = (wa * z[0] + wb * z[1] + wc * z[2]) / h.det;
  h.wb = wb;
  h.wc = wc;
  h.hit = ~outside & (h.det != 0.0f) & (h.t > tmin) & (h.t < tmax);
  return h;
}

/* Watertight: true when tmin < t < *t; then *t, barycentrics *u (weight of v1) and *v
 * (weight of v2). Both faces hit. A ray through an edge or vertex (an edge function exactly 0)
 * hits; a degenerate triangle or a zero direction never does. */
CLRT_INLINE bool intersect_triangle(float3 v0, float3 v1, float3 v2, float3 o, float3 d, float tmin,
                               float* t, float* u, float* v) {
  const TriangleRay r = triangle_ray(o, d);
  if (!r.valid) return false;
  const float3 vertex[3] = {v0, v1, v2};
  Triangle4 p;
  for (int j = 0; j < 3; ++j) {
    p.x[j] = (float4)(triangle_component(vertex[j], r.kx));
    p.y[j] = (float4)(triangle_component(vertex[j], r.ky));
    p.z[j] = (float4)(triangle_component(vertex[j], r.kz));
  }
  const Triangle4Hits h = triangle4_test(&r, &p, tmin, *t);
  if (!h.hit.x) return false;
  *t = h.t.x;
  *u = h.wb.x / h.det.x;
  *v = h.wc.x / h.det.x;
  return true;
}

/* Unnormalised geometric normal cross3(v1 - v0, v2 - v0): front face = counter-clockwise. */
CLRT_INLINE float3 triangle_normal(float3 v0, float3 v1, float3 v2) {
  return cross3(v1 - v0, v2 - v0);
}

#endif
