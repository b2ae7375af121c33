/* The path-tracing reading of a .ray material (docs/path-tracing.md, "Materials"): a mixture of
 * lobes, one row each in CLRT_LOBES with its device file in lobes/, whose NAME_lobe_* functions
 * give its albedo from the material, its share of the samples, its value and density, and a
 * direction drawn from it. The build includes every file of lobes/ (lobe_files.h, written by
 * tools/cmake/KindLists.cmake) and the mixture below is written over the rows, so a new lobe is
 * its file and its row. */
#ifndef CLRT_RENDER_LOBES_H
#define CLRT_RENDER_LOBES_H

#include "lobe_files.h"
#include "shared/lobe_kinds.h"

/* In the order a lobe is chosen from the mixture's random number. */
#define CLRT_LOBES(X) X(LAMBERT, lambert) X(PHONG, phong) X(MIRROR, mirror) X(GLASS, glass)
#define CLRT_LOBE_VALUE(LOBE, name) CLRT_LOBE_##LOBE,
enum { CLRT_LOBES(CLRT_LOBE_VALUE) CLRT_LOBE_COUNT };
#undef CLRT_LOBE_VALUE

/* Every file of lobes/ has its row: a file without one stops the build here (CLRT_LOBE_NAME
 * undeclared), and a row without a file at its functions below. */
#define CLRT_LOBE_HAS_ROW(LOBE, name) CLRT_LOBE_FILE_##LOBE = CLRT_LOBE_##LOBE,
enum { CLRT_LOBE_KINDS(CLRT_LOBE_HAS_ROW) CLRT_LOBE_FILE_COUNT };
#undef CLRT_LOBE_HAS_ROW

typedef struct PathLobes {
  float3 albedo[CLRT_LOBE_COUNT]; /* each lobe's weight w_k (grey but for the Lambertian's) */
  float choice[CLRT_LOBE_COUNT];  /* the probability of drawing from each */
} PathLobes;

/* The lobes' albedos, scaled down together when their largest sum exceeds 1 (energy
 * conservation), and the probabilities of drawing from them, in proportion to their albedos. */
CLRT_INLINE PathLobes path_lobes(MaterialRef m) {
  PathLobes l;
  const float share = local_share(m);
  float most = 0.0f;
#define CLRT_LOBE_ALBEDO(LOBE, name)                                  \
  l.albedo[CLRT_LOBE_##LOBE] = name##_lobe_albedo(m, share);          \
  most += max3(l.albedo[CLRT_LOBE_##LOBE]);
  CLRT_LOBES(CLRT_LOBE_ALBEDO)
#undef CLRT_LOBE_ALBEDO
  if (most > 1.0f)
    for (uint k = 0; k < CLRT_LOBE_COUNT; ++k) l.albedo[k] /= most;
  float total = 0.0f;
#define CLRT_LOBE_CHOICE(LOBE, name)                                                \
  l.choice[CLRT_LOBE_##LOBE] = name##_lobe_choice_weight(l.albedo[CLRT_LOBE_##LOBE]); \
  total += l.choice[CLRT_LOBE_##LOBE];
  CLRT_LOBES(CLRT_LOBE_CHOICE)
#undef CLRT_LOBE_CHOICE
  const float scale = total > 0.0f ? 1.0f / total : 0.0f;
  for (uint k = 0; k < CLRT_LOBE_COUNT; ++k) l.choice[k] *= scale;
  return l;
}

/* The mixture's BSDF for light arriving along wi and leaving along wo, zero below the surface
 * (only the dielectric, a delta lobe, transmits), and in *pdf the solid-angle density with which
 * the lobes, as chosen by their probabilities, draw wi: the density multiple importance sampling
 * weighs light samples against. */
CLRT_INLINE float3 smooth_lobes(const PathLobes* l, MaterialRef m, float3 n, float3 wo,
                                float3 wi, float* pdf) {
  const float cos_i = dot3(n, wi);
  *pdf = 0.0f;
  if (cos_i <= 0.0f) return (float3)(0.0f);
  float3 f = (float3)(0.0f);
#define CLRT_LOBE_SUM(LOBE, name)                                                             \
  f += name##_lobe_value(l->albedo[CLRT_LOBE_##LOBE], l->choice[CLRT_LOBE_##LOBE], m, n, wo, wi, \
                         cos_i, pdf);
  CLRT_LOBES(CLRT_LOBE_SUM)
#undef CLRT_LOBE_SUM
  if (dot3(n, wo) <= 0.0f) return (float3)(0.0f);
  return f;
}

/* The lobe that x in [0, 1) chooses, each taking the run of x its probability covers, and in *y
 * where x lies within that run, rescaled to [0, 1). An x that rounding leaves past every run
 * goes to the last lobe when it has any probability; otherwise CLRT_LOBE_COUNT: no lobe. */
CLRT_INLINE uint choose_lobe(const PathLobes* l, float x, float* y) {
  float start = 0.0f;
  for (uint k = 0; k < CLRT_LOBE_COUNT; ++k) {
    const float end = start + l->choice[k];
    if (x < end || (k + 1u == CLRT_LOBE_COUNT && l->choice[k] > 0.0f)) {
      *y = (x - start) / l->choice[k];
      return k;
    }
    start = end;
  }
  return CLRT_LOBE_COUNT;
}

/* A direction drawn from lobe k alone, with the pair u, and y in [0, 1) for a choice within the
 * lobe (the dielectric's between reflection and refraction); false when it draws none. */
CLRT_INLINE bool draw_lobe(const PathLobes* l, uint k, MaterialRef m, const ShadePoint* sp,
                           float3 d, float2 u, float y, LobeSample* s) {
  switch (k) {
#define CLRT_LOBE_DRAW(LOBE, name)                                                                  \
    case CLRT_LOBE_##LOBE:                                                                          \
      return name##_lobe_sample(l->albedo[CLRT_LOBE_##LOBE], l->choice[CLRT_LOBE_##LOBE], m, sp, d, \
                                u, y, s);
    CLRT_LOBES(CLRT_LOBE_DRAW)
#undef CLRT_LOBE_DRAW
  }
  return false;
}

/* Whether lobe k is smooth (it has a value and a density for a pair of directions) rather than a
 * delta lobe. */
CLRT_INLINE bool lobe_is_smooth(uint k) {
  switch (k) {
#define CLRT_LOBE_SMOOTH_CASE(LOBE, name) \
    case CLRT_LOBE_##LOBE: return name##_lobe_is_smooth();
    CLRT_LOBES(CLRT_LOBE_SMOOTH_CASE)
#undef CLRT_LOBE_SMOOTH_CASE
  }
  return false;
}

/* Whether a smooth lobe may be drawn: only then can a light sample add anything. */
CLRT_INLINE bool has_smooth_lobes(const PathLobes* l) {
  float smooth = 0.0f;
  for (uint k = 0; k < CLRT_LOBE_COUNT; ++k)
    if (lobe_is_smooth(k)) smooth += l->choice[k];
  return smooth > 0.0f;
}

/* A direction drawn from the mixture with the pair u and x in [0, 1) for the lobe: false when
 * the path ends here. A smooth lobe's direction is weighed by the whole mixture's value and
 * density (f cos / pdf, and *pdf for MIS); a delta lobe's by itself (*pdf = 0). */
CLRT_INLINE bool sample_lobes(const PathLobes* l, MaterialRef m, const ShadePoint* sp,
                              float3 d, float2 u, float x, LobeSample* s, float* pdf) {
  *pdf = 0.0f;
  float y = 0.0f;
  const uint k = choose_lobe(l, x, &y);
  if (k == CLRT_LOBE_COUNT || !draw_lobe(l, k, m, sp, d, u, y, s)) return false;
  if (!s->smooth) return true;
  const float3 f = smooth_lobes(l, m, sp->n, sp->v, s->dir, pdf);
  if (!(*pdf > 0.0f)) return false;
  s->weight = f * (dot3(sp->n, s->dir) / *pdf);
  return true;
}

#endif
