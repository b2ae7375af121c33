/* The optics both transport models share: mirror reflection, Snell's law, the Fresnel
 * reflectance of a smooth dielectric, and the share of a material's colour that its local
 * terms keep. */
#ifndef CLRT_RENDER_OPTICS_H
#define CLRT_RENDER_OPTICS_H

#include "common.h"

/* The mirror image of w about n (the contract's R = 2N(N.L) - L). */
CLRT_INLINE float3 mirror_about(float3 w, float3 n) { return 2.0f * dot3(n, w) * n - w; }

/* A ray travelling along d, reflected by a surface with normal n. */
CLRT_INLINE float3 reflect_dir(float3 d, float3 n) { return mirror_about(-d, n); }

/* The squared sine of the refracted angle for incidence cos_i and eta = n_incident /
 * n_transmitted; 1 or more means total internal reflection. */
CLRT_INLINE float refracted_sin2(float cos_i, float eta) { return eta * eta * (1.0f - cos_i * cos_i); }

/* The refracted direction of unit d through unit n (facing against d), given the incident and
 * transmitted cosines. */
CLRT_INLINE float3 refracted_dir(float3 d, float3 n, float eta, float cos_i, float cos_t) {
  return normalize3(eta * d + (eta * cos_i - cos_t) * n);
}

/* Fresnel reflectance of a smooth dielectric for unpolarised light: cos_i of the incident ray
 * against the normal on its side, eta = n_incident / n_transmitted; *cos_t is the transmitted
 * cosine. Total internal reflection gives 1. */
CLRT_INLINE float fresnel_dielectric(float cos_i, float eta, float* cos_t) {
  const float sin2_t = refracted_sin2(cos_i, eta);
  if (sin2_t >= 1.0f) {
    *cos_t = 0.0f;
    return 1.0f;
  }
  const float ct = sqrt(1.0f - sin2_t);
  *cos_t = ct;
  const float rs = (eta * cos_i - ct) / (eta * cos_i + ct);
  const float rp = (cos_i - eta * ct) / (cos_i + eta * ct);
  return 0.5f * (rs * rs + rp * rp);
}

/* The share of the local colour: 1 - kr - kt, clamped to >= 0. */
CLRT_INLINE float local_share(MaterialRef m) { return fmax(0.0f, 1.0f - m->kr - m->kt); }

#endif
