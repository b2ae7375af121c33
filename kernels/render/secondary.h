/* Reflection and refraction rays leaving a hit. */
#ifndef CLRT_RENDER_SECONDARY_H
#define CLRT_RENDER_SECONDARY_H

#include "common.h"
#include "random.h"

/* d mirrored about n (the contract's R = -E + 2N(E.N) with E = -d). */
CLRT_INLINE float3 reflect_dir(float3 d, float3 n) { return d - 2.0f * dot3(d, n) * n; }

/* Snell refraction of unit d through unit n (facing against d) with eta = n1 / n2. Returns
 * false on total internal reflection. */
CLRT_INLINE bool refract_dir(float3 d, float3 n, float eta, float3* t) {
  const float cos_i = -dot3(d, n);
  const float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
  if (k < 0.0f) return false;
  *t = normalize3(eta * d + (eta * cos_i - sqrt(k)) * n);
  return true;
}

/* A child keeps its camera sample's index (dir.w: path mode's Sobol samples need it; 0 in the
 * Whitted modes) and takes a stream of its own from its parent's and the branch. */
CLRT_INLINE Ray child_ray(const Ray* parent, float3 origin, float3 dir, float share, uint branch,
                     uint kind) {
  Ray r;
  r.origin = as_f4(origin);
  r.dir = (f4)(dir, parent->dir.w);
  r.weight = as_f4(xyz(parent->weight) * share);
  r.sample = parent->sample;
  r.depth = parent->depth + 1u;
  r.path = child_path(parent->path, branch);
  r.kind = kind;
  return r;
}

#endif
