/* The smooth dielectric: albedo kt, a delta lobe that reflects with the Fresnel reflectance and
 * refracts otherwise. */
#ifndef CLRT_RENDER_LOBES_GLASS_H
#define CLRT_RENDER_LOBES_GLASS_H

#include "../lobe_sample.h"

CLRT_INLINE float3 glass_lobe_albedo(MaterialRef m, float share) {
  return (float3)(fmax(0.0f, m->kt));
}

CLRT_INLINE bool glass_lobe_is_smooth(void) { return false; }

CLRT_INLINE float glass_lobe_choice_weight(float3 albedo) { return albedo.x; }

CLRT_INLINE float3 glass_lobe_value(float3 albedo, float choice, MaterialRef m,
                                    float3 n, float3 wo, float3 wi, float cos_i, float* pdf) {
  return (float3)(0.0f);
}

/* y in [0, 1) chooses between reflection (y below the Fresnel reflectance) and refraction. */
CLRT_INLINE bool glass_lobe_sample(float3 albedo, float choice, MaterialRef m,
                                   const ShadePoint* sp, float3 d, float2 u, float y, LobeSample* s) {
  const float cos_i = -dot3(d, sp->n);
  const float eta = sp->front ? 1.0f / m->ior : m->ior;
  float cos_t;
  const float f = fresnel_dielectric(cos_i, eta, &cos_t);
  const float share = albedo.x / choice;
  if (y < f) {
    *s = delta_sample(reflect_dir(d, sp->n), share, CLRT_RAY_REFLECTION, 1.0f);
  } else {
    /* radiance compressed into the denser medium's smaller solid angle */
    const float radiance_scale = eta * eta;
    *s = delta_sample(refracted_dir(d, sp->n, eta, cos_i, cos_t), share * radiance_scale,
                      CLRT_RAY_REFRACTION, radiance_scale);
  }
  return true;
}

#endif
