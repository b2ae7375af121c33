/* The Lambertian lobe: albedo (1 - kr - kt)+ kd C, value albedo / pi, drawn by cosine. */
#ifndef CLRT_RENDER_LOBES_LAMBERT_H
#define CLRT_RENDER_LOBES_LAMBERT_H

#include "../lobe_sample.h"

CLRT_INLINE float3 lambert_lobe_albedo(MaterialRef m, float share) {
  return share * m->kd * xyz(m->color);
}

/* Its colour's mean: the share of the samples it draws. */
CLRT_INLINE bool lambert_lobe_is_smooth(void) { return true; }

CLRT_INLINE float lambert_lobe_choice_weight(float3 albedo) { return mean3(albedo); }

/* Its value for light arriving along wi (cos_i = n.wi > 0); *pdf += choice times its density. */
CLRT_INLINE float3 lambert_lobe_value(float3 albedo, float choice, MaterialRef m,
                                      float3 n, float3 wo, float3 wi, float cos_i, float* pdf) {
  *pdf += choice * cos_i * CLRT_INV_PI;
  return albedo * CLRT_INV_PI;
}

CLRT_INLINE bool lambert_lobe_sample(float3 albedo, float choice, MaterialRef m,
                                     const ShadePoint* sp, float3 d, float2 u, float y, LobeSample* s) {
  *s = smooth_sample(sample_cosine(sp->n, u));
  return true;
}

#endif
