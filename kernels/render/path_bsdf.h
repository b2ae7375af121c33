/* The path-tracing reading of a .ray material (docs/path-tracing.md, "Materials"): a mixture of
 * a Lambertian, a normalised Phong, an ideal mirror and a smooth dielectric lobe. Directions are
 * unit vectors leaving the surface point; n is the shading normal, turned towards the viewer. */
#ifndef CLRT_RENDER_PATH_BSDF_H
#define CLRT_RENDER_PATH_BSDF_H

#include "common.h"

#define CLRT_INV_PI 0.318309873f
#define CLRT_INV_TWO_PI 0.159154937f

typedef struct PathLobes {
  float3 diffuse; /* w_d: the Lambertian lobe's albedo */
  float glossy;   /* w_g */
  float mirror;   /* w_m */
  float glass;    /* w_t */
  float exponent; /* the Phong exponent n */
  /* the probability of choosing each lobe, in the order above */
  float p_diffuse, p_glossy, p_mirror, p_glass;
} PathLobes;

CLRT_INLINE float max3(float3 v) { return fmax(v.x, fmax(v.y, v.z)); }
CLRT_INLINE float mean3(float3 v) { return (v.x + v.y + v.z) * (1.0f / 3.0f); }

CLRT_INLINE PathLobes path_lobes(__global const Material* m) {
  PathLobes l;
  const float share = fmax(0.0f, 1.0f - m->kr - m->kt); /* (1 - kr - kt)+ */
  float3 d = share * m->kd * xyz(m->color);
  float g = share * m->ks, r = fmax(0.0f, m->kr), t = fmax(0.0f, m->kt);
  const float most = max3(d) + g + r + t;
  if (most > 1.0f) {
    d /= most;
    g /= most;
    r /= most;
    t /= most;
  }
  l.diffuse = d;
  l.glossy = g;
  l.mirror = r;
  l.glass = t;
  l.exponent = m->shininess;
  const float total = mean3(d) + g + r + t;
  const float scale = total > 0.0f ? 1.0f / total : 0.0f;
  l.p_diffuse = mean3(d) * scale;
  l.p_glossy = g * scale;
  l.p_mirror = r * scale;
  l.p_glass = t * scale;
  return l;
}

/* The mirror image of w about n. */
CLRT_INLINE float3 mirror_about(float3 w, float3 n) { return 2.0f * dot3(n, w) * n - w; }

/* The two smooth lobes' BSDF for light arriving along wi and leaving along wo; zero below the
 * surface (only the dielectric, a delta lobe, transmits). */
CLRT_INLINE float3 smooth_bsdf(const PathLobes* l, float3 n, float3 wo, float3 wi) {
  if (dot3(n, wi) <= 0.0f || dot3(n, wo) <= 0.0f) return (float3)(0.0f);
  const float phong = l->glossy == 0.0f ? 0.0f : power(fmax(0.0f, dot3(mirror_about(wi, n), wo)), l->exponent);
  return l->diffuse * CLRT_INV_PI + l->glossy * (l->exponent + 2.0f) * CLRT_INV_TWO_PI * phong;
}

/* The solid-angle density with which the smooth lobes, as chosen by their probabilities, draw
 * wi: the density multiple importance sampling weighs light samples against. */
CLRT_INLINE float smooth_pdf(const PathLobes* l, float3 n, float3 wo, float3 wi) {
  const float cos_i = dot3(n, wi);
  if (cos_i <= 0.0f) return 0.0f;
  const float phong = l->p_glossy == 0.0f ? 0.0f : power(fmax(0.0f, dot3(mirror_about(wo, n), wi)), l->exponent);
  return l->p_diffuse * cos_i * CLRT_INV_PI +
         l->p_glossy * (l->exponent + 1.0f) * CLRT_INV_TWO_PI * phong;
}

/* A unit vector at polar cosine cos_theta and azimuth 2 pi u about the unit axis a, built in a
 * branch-free orthonormal basis (Duff et al., JCGT 2017). */
CLRT_INLINE float3 around_axis(float3 a, float cos_theta, float u) {
  const float sign = a.z >= 0.0f ? 1.0f : -1.0f;
  const float k = -1.0f / (sign + a.z);
  const float b = a.x * a.y * k;
  const float3 t = (float3)(1.0f + sign * a.x * a.x * k, sign * b, -sign * a.x);
  const float3 bt = (float3)(b, sign + a.y * a.y * k, -a.y);
  const float sin_theta = sqrt(fmax(0.0f, 1.0f - cos_theta * cos_theta));
  float s, c;
  sincos_turns(u, &s, &c);
  return normalize3((sin_theta * c) * t + (sin_theta * s) * bt + cos_theta * a);
}

/* Cosine-weighted about n. */
CLRT_INLINE float3 sample_cosine(float3 n, float2 u) { return around_axis(n, sqrt(1.0f - u.x), u.y); }

/* The Phong lobe's density (n + 1) / (2 pi) cos^n about the mirror direction of wo. */
CLRT_INLINE float3 sample_phong(float3 n, float3 wo, float exponent, float2 u) {
  return around_axis(mirror_about(wo, n), power(1.0f - u.x, 1.0f / (exponent + 1.0f)), u.y);
}

/* Fresnel reflectance of a smooth dielectric for unpolarised light: cos_i of the incident ray
 * against the normal on its side, eta = n_incident / n_transmitted; *cos_t is the transmitted
 * cosine. Total internal reflection gives 1. */
CLRT_INLINE float fresnel_dielectric(float cos_i, float eta, float* cos_t) {
  const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
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

#endif
