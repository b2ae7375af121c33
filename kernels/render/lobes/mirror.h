/* The ideal mirror: albedo kr, a delta lobe along the mirror direction. */
#ifndef CLRT_RENDER_LOBES_MIRROR_H
#define CLRT_RENDER_LOBES_MIRROR_H

#include "../lobe_sample.h"

CLRT_INLINE float3 mirror_lobe_albedo(MaterialRef m, float share) {
  return (float3)(fmax(0.0f, m->kr));
}

CLRT_INLINE bool mirror_lobe_is_smooth(void) { return false; }

CLRT_INLINE float mirror_lobe_choice_weight(float3 albedo) { return albedo.x; }

/* A delta lobe has no value for a given pair of directions. */
CLRT_INLINE float3 mirror_lobe_value(float3 albedo, float choice, MaterialRef m,
                                     float3 n, float3 wo, float3 wi, float cos_i, float* pdf) {
  return (float3)(0.0f);
}

CLRT_INLINE bool mirror_lobe_sample(float3 albedo, float choice, MaterialRef m,
                                    const ShadePoint* sp, float3 d, float2 u, float y, LobeSample* s) {
  *s = delta_sample(reflect_dir(d, sp->n), albedo.x / choice, CLRT_RAY_REFLECTION, 1.0f);
  return true;
}

#endif
