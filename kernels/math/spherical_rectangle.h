/* Points of a rectangle drawn uniformly in the solid angle it subtends from a point o, after
 * Urena, Fajardo and King, "An Area-Preserving Parametrization for Spherical Rectangles" (EGSR
 * 2013): a pair (u, v) in the unit square maps to a point of the rectangle such that equal areas
 * of the square go to equal solid angles, so a sample's density is 1 / (the solid angle) and a
 * stratified pair stays stratified in solid angle. The rectangle is seen in its own frame
 * (x along its first edge, y along its second, z away from o): o at the origin, the rectangle
 * spanning [x0, x1] x [y0, y1] at height z0 < 0.
 *
 * The solid angle is the sum of the four interior angles of the spherical quadrilateral less
 * 2 pi. Each angle less pi/2 is the arcsine of the dot product of the two planes' unit normals
 * through o and its two edges, which here reduces to atan(x y / (|z0| r)) for that corner
 * (x, y, z0) at distance r, with the signs of the corner's side: summing those four small angles
 * keeps the digits that 2 pi less four near right angles would cancel. */
#ifndef CLRT_MATH_SPHERICAL_RECTANGLE_H
#define CLRT_MATH_SPHERICAL_RECTANGLE_H

#include "exact.h"

typedef struct SphericalRectangle {
  float3 x, y, z;            /* the frame: unit edges and the normal pointing away from o */
  float x0, x1, y0, y1, z0;  /* the rectangle in that frame, o at the origin */
  float excess23;            /* the angles at corners (x0, y1) and (x0, y0), less pi/2 each */
  float b0, b1;              /* the z of the normals of the planes through the y0 and y1 edges */
  float solid_angle;
} SphericalRectangle;

/* atan(a) + atan(b) with one arctangent: the angle whose tangent is (a + b) / (1 - a b), in the
 * half-turn beyond +-pi/2 when 1 - a b < 0 (pi as a float and its remainder). */
CLRT_INLINE float atan_sum(float a, float b) {
  const float y = a + b, x = 1.0f - a * b;
  if (x == 0.0f) return y < 0.0f ? -1.57079637f : 1.57079637f;
  const float angle = exact_atan(y / x);
  if (x > 0.0f) return angle;
  return y < 0.0f ? (angle - 3.14159274f) + 8.74227766e-08f : (angle + 3.14159274f) - 8.74227766e-08f;
}

/* The rectangle with corner c and perpendicular edges eu and ev of lengths lu and lv, unit
 * normal n, seen from o. */
CLRT_INLINE SphericalRectangle spherical_rectangle(float3 c, float3 eu, float lu, float3 ev, float lv,
                                                   float3 n, float3 o) {
  SphericalRectangle r;
  r.x = eu / lu;
  r.y = ev / lv;
  r.z = n;
  const float3 d = c - o;
  r.x0 = dot3(d, r.x);
  r.y0 = dot3(d, r.y);
  r.z0 = dot3(d, r.z);
  if (r.z0 > 0.0f) {
    r.z0 = -r.z0;
    r.z = -r.z;
  }
  r.x1 = r.x0 + lu;
  r.y1 = r.y0 + lv;
  const float h = -r.z0, h2 = r.z0 * r.z0;
  const float x02 = r.x0 * r.x0, x12 = r.x1 * r.x1, y02 = r.y0 * r.y0, y12 = r.y1 * r.y1;
  /* Each corner's angle less pi/2 is atan(x y / (h r)), signed by the sides it lies between. */
  const float t0 = -(r.x1 * r.y0) / (h * sqrt(x12 + y02 + h2));
  const float t1 = (r.x1 * r.y1) / (h * sqrt(x12 + y12 + h2));
  const float t2 = -(r.x0 * r.y1) / (h * sqrt(x02 + y12 + h2));
  const float t3 = (r.x0 * r.y0) / (h * sqrt(x02 + y02 + h2));
  r.excess23 = atan_sum(t2, t3);
  r.solid_angle = atan_sum(t0, t1) + r.excess23;
  r.b0 = -r.y0 / sqrt(h2 + y02);
  r.b1 = r.y1 / sqrt(h2 + y12);
  return r;
}

/* The point of the rectangle that (u, v) in [0, 1]^2 maps to, relative to o. */
CLRT_INLINE float3 spherical_rectangle_point(const SphericalRectangle* r, float2 uv) {
  /* The angle a_u = u S + 2 pi - g2 - g3 of the paper is pi + phi with phi below: its sine and
   * cosine are those of phi, negated, so the quotient f_u keeps their ratio. */
  const float phi = uv.x * r->solid_angle - r->excess23;
  float turns = fabs(phi) * 0.159154937f; /* 1 / (2 pi) */
  if (turns >= 1.0f) turns -= 1.0f;
  float sin_phi, cos_phi;
  sincos_turns(turns, &sin_phi, &cos_phi);
  if (phi < 0.0f) sin_phi = -sin_phi;
  const float fu = (cos_phi * r->b0 + r->b1) / sin_phi;
  const float cu = clamp((fu > 0.0f ? 1.0f : -1.0f) / sqrt(fu * fu + r->b0 * r->b0), -1.0f, 1.0f);
  /* fmin and fmax also turn a NaN (from a zero sine at the square's edge) into an edge. */
  const float xu = fmax(r->x0, fmin(r->x1, -(cu * r->z0) / sqrt(1.0f - cu * cu)));
  const float d2 = xu * xu + r->z0 * r->z0, d = sqrt(d2);
  const float h0 = r->y0 / sqrt(d2 + r->y0 * r->y0), h1 = r->y1 / sqrt(d2 + r->y1 * r->y1);
  const float hv = h0 + uv.y * (h1 - h0), hv2 = hv * hv;
  const float yv = hv2 < 0.999999f ? fmax(r->y0, fmin(r->y1, hv * d / sqrt(1.0f - hv2))) : r->y1;
  return xu * r->x + yv * r->y + r->z0 * r->z;
}

#endif
