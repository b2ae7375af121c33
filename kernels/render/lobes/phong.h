/* The normalised Phong lobe: albedo (1 - kr - kt)+ ks, value albedo (n + 2) / (2 pi) cos^n about
 * the mirror direction of wo, drawn with density (n + 1) / (2 pi) cos^n. */
#ifndef CLRT_RENDER_LOBES_PHONG_H
#define CLRT_RENDER_LOBES_PHONG_H

#include "../lobe_sample.h"

/* The Phong factor max(0, R.wi)^n with R the mirror image of wo about n, for any exponent the
 * reader accepts. Near the lobe's axis 1 - cos is taken from |R - wi|^2 / 2, which keeps its
 * digits where the cosine itself rounds to 1 or above it (at an exponent of 1e9 a cosine
 * rounded to 1 + 2^-23 gave infinity), and the power is exp2(n log2 cos) with log2 cos <= 0, so
 * the factor never exceeds 1. Exponent 0 gives 1 everywhere (0^0 = 1, as the contract has it).
 * The value and the density both come from one call with (wo, wi) in that order, so a sample's
 * f / pdf does not depend on how each rounded. */
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

/* The density with which the lobe draws wi (cos_i = n.wi > 0), given its factor there:
 * (n + 1) / (2 pi) cos^n about the mirror direction, except at exponent 0, where the lobe is
 * 1 / pi over the whole hemisphere, a Lambertian, and is drawn as one, by cosine. */
CLRT_INLINE float phong_pdf(float cos_i, float exponent, float phong) {
  if (exponent == 0.0f) return cos_i * CLRT_INV_PI;
  return (exponent + 1.0f) * CLRT_INV_TWO_PI * phong;
}

CLRT_INLINE float3 phong_lobe_albedo(MaterialRef m, float share) {
  return (float3)(share * m->ks);
}

CLRT_INLINE bool phong_lobe_is_smooth(void) { return true; }

CLRT_INLINE float phong_lobe_choice_weight(float3 albedo) { return albedo.x; }

CLRT_INLINE float3 phong_lobe_value(float3 albedo, float choice, MaterialRef m,
                                    float3 n, float3 wo, float3 wi, float cos_i, float* pdf) {
  const float exponent = m->shininess;
  const float phong = albedo.x == 0.0f ? 0.0f : phong_factor(n, wo, wi, exponent);
  *pdf += choice * (choice == 0.0f ? 0.0f : phong_pdf(cos_i, exponent, phong));
  return albedo * (exponent + 2.0f) * CLRT_INV_TWO_PI * phong;
}

/* cos = (1 - u)^(1 / (n + 1)) by inversion, with 1 - cos (and so the sine) computed directly,
 * so that a narrow lobe (exponents of 1e4 and beyond) keeps its shape instead of collapsing
 * onto its axis. */
CLRT_INLINE float3 sample_phong(float3 n, float3 wo, float exponent, float2 u) {
  if (exponent == 0.0f) return sample_cosine(n, u);
  const float delta = one_minus_exp2(exact_log2(1.0f - u.x) / (exponent + 1.0f));
  return around_axis(mirror_about(wo, n), 1.0f - delta, sqrt(delta * (2.0f - delta)), u.y);
}

CLRT_INLINE bool phong_lobe_sample(float3 albedo, float choice, MaterialRef m,
                                   const ShadePoint* sp, float3 d, float2 u, float y, LobeSample* s) {
  *s = smooth_sample(sample_phong(sp->n, sp->v, m->shininess, u));
  return true;
}

#endif
