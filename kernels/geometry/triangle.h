/* Ray-triangle intersection: the watertight test of Woop, Benthin and Wald (JCGT 2013).
 *
 * Why not Moller-Trumbore: it measures each triangle's edges from that triangle's own first
 * vertex, so the two triangles sharing an edge round differently and a ray through the edge
 * can miss both; in closed meshes those cracks show up as speckles, worst for refraction and
 * shadow rays that hit edges at grazing angles. Here the ray is sheared to run along +z and
 * every edge function depends only on the ray and the edge's two vertices, evaluated in the
 * same way by both triangles (with contraction into fma off, so the two results are exact
 * negatives): a ray through a shared edge or vertex hits at least one of the triangles. The
 * per-ray shear depends only on o and d, so inlined in a leaf loop it is loop-invariant. */
#ifndef CLRT_GEOMETRY_TRIANGLE_H
#define CLRT_GEOMETRY_TRIANGLE_H

/* Component k (0, 1 or 2) of v. */
inline float triangle_component(float3 v, int k) {
  return k == 0 ? v.x : (k == 1 ? v.y : v.z);
}

/* p relative to the ray origin, in the frame where the ray runs along +z from 0 and has unit
 * z speed: xy across the ray, z = the t at which the ray passes p's depth. */
inline float3 triangle_shear(float3 p, int kx, int ky, int kz, float3 shear) {
#pragma OPENCL FP_CONTRACT OFF
  const float pz = triangle_component(p, kz);
  return (float3)(triangle_component(p, kx) - shear.x * pz,
                  triangle_component(p, ky) - shear.y * pz, shear.z * pz);
}

/* Watertight: true when tmin < t < *t; then *t, barycentrics *u (weight of v1) and *v
 * (weight of v2). Both faces hit. A ray through an edge or vertex (an edge function exactly 0)
 * hits; a degenerate triangle or a zero direction never does. */
inline bool intersect_triangle(float3 v0, float3 v1, float3 v2, float3 o, float3 d, float tmin,
                               float* t, float* u, float* v) {
#pragma OPENCL FP_CONTRACT OFF
  const float3 ad = fabs(d);
  /* The dominant axis becomes z; swapping x and y for a negative d.z keeps the winding. */
  const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
  int kx = kz == 2 ? 0 : kz + 1;
  int ky = kx == 2 ? 0 : kx + 1;
  const float dz = triangle_component(d, kz);
  if (dz == 0.0f) return false;
  if (dz < 0.0f) {
    const int swap = kx;
    kx = ky;
    ky = swap;
  }
  const float3 shear = (float3)(triangle_component(d, kx) / dz, triangle_component(d, ky) / dz,
                                1.0f / dz);
  const float3 a = triangle_shear(v0 - o, kx, ky, kz, shear);
  const float3 b = triangle_shear(v1 - o, kx, ky, kz, shear);
  const float3 c = triangle_shear(v2 - o, kx, ky, kz, shear);
  /* Twice the signed areas seen along the ray, each opposite one vertex: its weight. */
  const float wa = c.x * b.y - c.y * b.x;
  const float wb = a.x * c.y - a.y * c.x;
  const float wc = b.x * a.y - b.y * a.x;
  if ((wa < 0.0f || wb < 0.0f || wc < 0.0f) && (wa > 0.0f || wb > 0.0f || wc > 0.0f))
    return false;
  const float det = wa + wb + wc;
  if (det == 0.0f) return false;
  const float t_hit = (wa * a.z + wb * b.z + wc * c.z) / det;
  if (!(t_hit > tmin && t_hit < *t)) return false;
  *t = t_hit;
  *u = wb / det;
  *v = wc / det;
  return true;
}

/* Unnormalised geometric normal cross(v1 - v0, v2 - v0): front face = counter-clockwise. */
inline float3 triangle_normal(float3 v0, float3 v1, float3 v2) {
  return cross(v1 - v0, v2 - v0);
}

#endif
