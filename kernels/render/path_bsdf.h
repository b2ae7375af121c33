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

/* The Phong factor max(0, R.wi)^n with R the mirror image of wo about n, for any exponent the
 * reader accepts. Near the lobe's axis 1 - cos is taken from |R - wi|^2 / 2, which keeps its
 * digits where the cosine itself rounds to 1 or above it (at an exponent of 1e9 a cosine
 * rounded to 1 + 2^-23 gave infinity), and the power is exp2(n log2 cos) with log2 cos <= 0, so
 * the factor never exceeds 1. Exponent 0 gives 1 everywhere (0^0 = 1, as the contract has it).
 * The BSDF and the density both call this with (wo, wi) in that order, so a sample's f / pdf
 * does not depend on how each rounded. */
CLRT_INLINE float phong_factor(float3 n, float3 wo, float3 wi, float exponent) {
  if (exponent == 0.0f) return 1.0f;
  const float3 r = mirror_about(wo, n);
  const float c = dot3(r, wi);
  if (!(c > 0.0f)) return 0.0f;
  if (c < 0.75f) return exact_exp2(exponent * exact_log2(c));
  const float3 d = r - wi;
  const float delta = 0.5f * dot3(d, d); /* 1 - cos */
  /* cos = (1 - s) / (1 + s) with s = delta / (2 - delta) */
  return exact_exp2(-exponent * log2_ratio_series(delta / (2.0f - delta)));
}

/* The density with which the Phong lobe draws wi (cos_i = n.wi > 0), given its factor there:
 * (n + 1) / (2 pi) cos^n about the mirror direction, except at exponent 0, where the lobe is
 * 1 / pi over the whole hemisphere, a Lambertian, and is drawn as one, by cosine. */
CLRT_INLINE float phong_pdf(float cos_i, float exponent, float phong) {
  if (exponent == 0.0f) return cos_i * CLRT_INV_PI;
  return (exponent + 1.0f) * CLRT_INV_TWO_PI * phong;
}

/* The two smooth lobes for light arriving along wi and leaving along wo: their BSDF, zero below
 * the surface (only the dielectric, a delta lobe, transmits), and in *pdf the solid-angle density
 * with which they, as chosen by their probabilities, draw wi (the density multiple importance
 * sampling weighs light samples against). One Phong factor serves both. */
CLRT_INLINE float3 smooth_lobes(const PathLobes* l, float3 n, float3 wo, float3 wi, float* pdf) {
  const float cos_i = dot3(n, wi);
  *pdf = 0.0f;
  if (cos_i <= 0.0f) return (float3)(0.0f);
  const float phong = l->glossy == 0.0f ? 0.0f : phong_factor(n, wo, wi, l->exponent);
  *pdf = l->p_diffuse * cos_i * CLRT_INV_PI +
         l->p_glossy * (l->p_glossy == 0.0f ? 0.0f : phong_pdf(cos_i, l->exponent, phong));
  if (dot3(n, wo) <= 0.0f) return (float3)(0.0f);
  return l->diffuse * CLRT_INV_PI + l->glossy * (l->exponent + 2.0f) * CLRT_INV_TWO_PI * phong;
}

/* A unit vector at polar angle theta (given as its cosine and sine) and azimuth 2 pi u about
 * the unit axis a, built in a branch-free orthonormal basis (Duff et al., JCGT 2017). */
CLRT_INLINE float3 around_axis(float3 a, float cos_theta, float sin_theta, float u) {
  const float sign = a.z >= 0.0f ? 1.0f : -1.0f;
  const float k = -1.0f / (sign + a.z);
  const float b = a.x * a.y * k;
  const float3 t = (float3)(1.0f + sign * a.x * a.x * k, sign * b, -sign * a.x);
  const float3 bt = (float3)(b, sign + a.y * a.y * k, -a.y);
  float s, c;
  sincos_turns(u, &s, &c);
  return normalize3((sin_theta * c) * t + (sin_theta * s) * bt + cos_theta * a);
}

/* Cosine-weighted about n. */
CLRT_INLINE float3 sample_cosine(float3 n, float2 u) {
  const float cos_theta = sqrt(1.0f - u.x);
  return around_axis(n, cos_theta, sqrt(fmax(0.0f, 1.0f - cos_theta * cos_theta)), u.y);
}

/* The Phong lobe's density phong_pdf about the mirror direction of wo: cos = (1 - u)^(1 / (n + 1))
 * by inversion, with 1 - cos (and so the sine) computed directly, so that a narrow lobe
 * (exponents of 1e4 and beyond) keeps its shape instead of collapsing onto its axis. */
CLRT_INLINE float3 sample_phong(float3 n, float3 wo, float exponent, float2 u) {
  if (exponent == 0.0f) return sample_cosine(n, u);
  const float delta = one_minus_exp2(exact_log2(1.0f - u.x) / (exponent + 1.0f));
  return around_axis(mirror_about(wo, n), 1.0f - delta, sqrt(delta * (2.0f - delta)), u.y);
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
