/* Ray intersection with the canonical objects of the scene format (ray-format.md): the unit
 * sphere, the plane y = 0, the cube [-1, 1]^3, and the cylinder and cone about the y axis with
 * y in [-1, 1]. Rays are in object space with an unnormalised direction, so t is the world t. */
#ifndef CLRT_GEOMETRY_SHAPES_H
#define CLRT_GEOMETRY_SHAPES_H

#include "math/exact.h"

#include "geometry/span.h"
#include "shared/scene.h"

CLRT_INLINE Span sphere_span(float3 o, float3 d) {
  const float a = dot3(d, d), b = dot3(o, d);
  /* b^2 - a c written as a (1 - |l|^2), l the point of the line nearest the centre: unlike
   * b^2 - a c it keeps its precision when the origin is far from the sphere. A zero d gives
   * NaN here, which the test below turns into a miss. */
  const float3 l = o - (b / a) * d;
  const float disc = a * (1.0f - dot3(l, l));
  if (!(disc >= 0.0f)) return span_empty();
  const float2 r = quadratic_roots(a, b, dot3(o, o) - 1.0f, disc);
  return span_make(r.x, o + r.x * d, r.y, o + r.y * d);
}

CLRT_INLINE Span cube_span(float3 o, float3 d) {
  Span s = slab_span(o.x, d.x, (float3)(1.0f, 0.0f, 0.0f));
  s = span_meet(s, slab_span(o.y, d.y, (float3)(0.0f, 1.0f, 0.0f)));
  return span_meet(s, slab_span(o.z, d.z, (float3)(0.0f, 0.0f, 1.0f)));
}

/* Outward normal of the side x^2 + z^2 = R(y)^2 with R(y) = m y + k: half the gradient of
 * x^2 + z^2 - R(y)^2. It vanishes at a cone's apex, where the axis pointing out of the apex
 * stands in (R grows away from the apex, so the apex is at the top when m < 0). */
CLRT_INLINE float3 side_normal(float3 p, float m, float k) {
  const float3 n = (float3)(p.x, -m * (m * p.y + k), p.z);
  if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f)
    return (float3)(0.0f, m < 0.0f ? 1.0f : -1.0f, 0.0f);
  return n;
}

/* Where the ray is inside x^2 + z^2 <= R(y)^2, i.e. where f(t) = a t^2 + 2 b t + c <= 0. For a
 * cone that solid is a double cone; between y = -1 and y = 1 only the nappe with R >= 0 lies
 * (the radii are >= 0 there), so the slab that follows removes the other one. */
CLRT_INLINE Span side_span(float3 o, float3 d, float m, float k) {
  /* Along the ray R = r_o + w t: r_o is R at the origin's height. */
  const float r_o = m * o.y + k, w = m * d.y;
  const float a = d.x * d.x + d.z * d.z - w * w;
  const float b = o.x * d.x + o.z * d.z - w * r_o;
  const float c = o.x * o.x + o.z * o.z - r_o * r_o;
  if (a == 0.0f) {
    /* Parallel to the axis of a cylinder, or to a line of a cone: f is linear or constant. */
    if (b == 0.0f) return c <= 0.0f ? span_all() : span_empty();
    const float r = -c / (2.0f * b);
    const float3 n = side_normal(o + r * d, m, k);
    return b > 0.0f ? span_make(-INFINITY, n, r, n) : span_make(r, n, INFINITY, n);
  }
  /* b^2 - a c rewritten by Lagrange's identity as |r_o d_xz - w o_xz|^2 - (o_xz x d_xz)^2.
   * Both terms vanish for a line through a cone's apex, where b^2 and a c are large and equal:
   * their float difference would put the double root off by sqrt(epsilon), not epsilon. */
  const float2 e = (float2)(r_o * d.x - w * o.x, r_o * d.z - w * o.z);
  const float across = o.x * d.z - o.z * d.x;
  const float disc = dot2(e, e) - across * across;
  /* No root: f keeps the sign of a (a < 0 only by rounding for a line through the apex). */
  if (disc < 0.0f) return a > 0.0f ? span_empty() : span_all();
  const float2 r = quadratic_roots(a, b, c, disc);
  const float3 n_lo = side_normal(o + r.x * d, m, k), n_hi = side_normal(o + r.y * d, m, k);
  if (a > 0.0f) return span_make(r.x, n_lo, r.y, n_hi);
  /* a < 0: the line is steeper than the cone and crosses both nappes; it is inside the double
   * cone before r.x and after r.y. Keep the half on the nappe with R >= 0: R = r_o + w t grows
   * without bound towards t = -infinity when w < 0. */
  return w < 0.0f ? span_make(-INFINITY, n_lo, r.x, n_lo) : span_make(r.y, n_hi, INFINITY, n_hi);
}

/* Radius r0 at y = -1 to r1 at y = 1 (r0, r1 >= 0, not both 0); the caps come from the slab,
 * which is passed first so that a ray through a rim or the apex takes the cap's normal. */
CLRT_INLINE Span frustum_span(float3 o, float3 d, float r0, float r1) {
  const float m = 0.5f * (r1 - r0), k = 0.5f * (r0 + r1);
  return span_meet(slab_span(o.y, d.y, (float3)(0.0f, 1.0f, 0.0f)), side_span(o, d, m, k));
}

CLRT_INLINE bool plane_hit(float3 o, float3 d, float tmin, float* t, float3* normal) {
  if (d.y == 0.0f) return false;
  const float t_hit = -o.y / d.y;
  if (!(t_hit > tmin && t_hit < *t)) return false;
  *t = t_hit;
  *normal = (float3)(0.0f, 1.0f, 0.0f);
  return true;
}

/* Closest intersection of the object-space ray o + t d (d NOT normalised, so t is the world t)
 * with canonical shape `shape` (sphere, plane, cube, cylinder, cone; not mesh) with
 * tmin < t < *t. On a hit: returns true, stores t in *t and the object-space outward normal
 * (not necessarily unit) in *normal. Otherwise returns false and leaves *t and *normal alone.
 * The closed objects include their boundary: a ray that only touches one (a tangent, a ray
 * along a face) hits it. A ray starting inside finds the exit. */
CLRT_INLINE bool intersect_canonical(u32 shape, float cone_r0, float cone_r1, float3 o, float3 d,
                                float tmin, float* t, float3* normal) {
  Span s;
  switch (shape) {
    case CLRT_SHAPE_SPHERE: s = sphere_span(o, d); break;
    case CLRT_SHAPE_PLANE: return plane_hit(o, d, tmin, t, normal);
    case CLRT_SHAPE_CUBE: s = cube_span(o, d); break;
    case CLRT_SHAPE_CYLINDER: s = frustum_span(o, d, 1.0f, 1.0f); break;
    case CLRT_SHAPE_CONE: s = frustum_span(o, d, cone_r0, cone_r1); break;
    default: return false;
  }
  return span_hit(s, tmin, t, normal);
}

#endif
