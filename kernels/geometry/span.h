/* The closed objects (sphere, cube, cylinder, cone) are convex, so a ray is inside one over a
 * single interval of t. Each is intersected as the meet of simpler convex pieces (slabs, the
 * inside of a quadric), which leaves no cracks where the pieces join (cube edges, cylinder
 * rims): there is no separate "is the hit point within the face" test to fail by rounding.
 * Infinite ends are +-INFINITY, so programs must not be built with -cl-finite-math-only or
 * -cl-fast-relaxed-math. */
#ifndef CLRT_GEOMETRY_SPAN_H
#define CLRT_GEOMETRY_SPAN_H

#include "math/exact.h"

/* The ray is inside for t in [t0, t1] (empty when t0 > t1), entering through a surface whose
 * outward normal is n0 and leaving through one whose outward normal is n1. */
typedef struct Span {
  float t0, t1;
  float3 n0, n1;
} Span;

CLRT_INLINE Span span_make(float t0, float3 n0, float t1, float3 n1) {
  Span s;
  s.t0 = t0;
  s.n0 = n0;
  s.t1 = t1;
  s.n1 = n1;
  return s;
}

/* The whole line: a constraint the ray satisfies everywhere. */
CLRT_INLINE Span span_all(void) {
  return span_make(-INFINITY, (float3)(0.0f), INFINITY, (float3)(0.0f));
}

CLRT_INLINE Span span_empty(void) {
  return span_make(INFINITY, (float3)(0.0f), -INFINITY, (float3)(0.0f));
}

/* Where the ray is inside both. On a tie the bound of `a` is kept, so callers pass the piece
 * whose normal should win on shared edges first. */
CLRT_INLINE Span span_meet(Span a, Span b) {
  if (b.t0 > a.t0) {
    a.t0 = b.t0;
    a.n0 = b.n0;
  }
  if (b.t1 < a.t1) {
    a.t1 = b.t1;
    a.n1 = b.n1;
  }
  return a;
}

/* The span of -1 <= o + t d <= 1 along one axis, whose unit vector is `axis`. A ray parallel
 * to the slab (d exactly 0) is inside everywhere or nowhere: no 0 / 0. */
CLRT_INLINE Span slab_span(float o, float d, float3 axis) {
  if (d == 0.0f) return fabs(o) <= 1.0f ? span_all() : span_empty();
  const float t_minus = (-1.0f - o) / d, t_plus = (1.0f - o) / d;
  return d > 0.0f ? span_make(t_minus, -axis, t_plus, axis)
                  : span_make(t_plus, axis, t_minus, -axis);
}

/* The first boundary of `s` in (tmin, *t): the entry, or the exit for a ray that starts
 * inside. Leaves *t and *normal alone when there is none. */
CLRT_INLINE bool span_hit(Span s, float tmin, float* t, float3* normal) {
  if (!(s.t0 <= s.t1)) return false;
  const bool entering = s.t0 > tmin;
  const float t_hit = entering ? s.t0 : s.t1;
  if (!(t_hit > tmin && t_hit < *t)) return false;
  *t = t_hit;
  *normal = entering ? s.n0 : s.n1;
  return true;
}

/* Both roots, in increasing order, of a t^2 + 2 b t + c = 0 with a != 0 and disc = b^2 - a c
 * >= 0, computed without cancellation (q and c / q instead of (-b +- sqrt(disc)) / a). */
CLRT_INLINE float2 quadratic_roots(float a, float b, float c, float disc) {
  const float q = -(b + copysign(sqrt(disc), b));
  /* q is 0 only for b = 0 and disc = 0: the double root at 0. */
  if (q == 0.0f) return (float2)(0.0f);
  const float r0 = q / a, r1 = c / q;
  return (float2)(fmin(r0, r1), fmax(r0, r1));
}

#endif
