/* The Whitted transport model (cast and trace modes): the contract's local terms at a hit, its
 * shadow rays, and its reflection and refraction rays, which it hands to its sink
 * (render/ray_sink.h), which queues them (wavefront) or follows them at once (megakernel). The
 * children are handed over refraction first, so that a depth-first stack pops the reflection
 * first: the tree order accumulate.cl sums in. The step returns the ray's own colour: its miss
 * colour, or its ambient term and its surface's emission plus (cast mode) every light's term or (trace mode) what the sink
 * added. */
#ifndef CLRT_RENDER_WHITTED_STEP_H
#define CLRT_RENDER_WHITTED_STEP_H

#include "light_loop.h"
#include "lobes/phong.h"

/* The hashed pair of a reflection ray's direction under --glossy (light samples use 0, 1, ...). */
#define CLRT_GLOSSY_DIRECTION 0xfffffffeu

/* kd * Ld * C * (N.L) + ks * Ld * max(0, R.V)^n, where R is L mirrored about N; zero when
 * N.L <= 0. 0^0 is 1 as the contract asks. R.V is held to at most 1, where rounding can leave
 * it: a little above 1 a large exponent (the reader accepts up to 1e12) overflows. */
CLRT_INLINE float3 direct_term(MaterialRef m, float3 n, float3 v, float3 l, float3 ld) {
  const float nl = dot3(n, l);
  if (nl <= 0.0f) return (float3)(0.0f);
  const float3 r = mirror_about(l, n);
  const float highlight = m->ks == 0.0f ? 0.0f : power(clamp(dot3(r, v), 0.0f, 1.0f), m->shininess);
  return m->kd * ld * xyz(m->color) * nl + m->ks * ld * highlight;
}

CLRT_INLINE float3 ambient_colour(const ShadePoint* s, MaterialRef m,
                                  __global const RenderParams* params) {
  return s->base * m->ka * xyz(params->ambient) * xyz(m->color);
}

struct TransportVertex {
  ShadePoint sp;
  uint path; /* the ray's random stream */
};

/* A hashed jitter for the sample's stratum. */
CLRT_INLINE float2 transport_light_pair(const TransportVertex* v, uint use) { return jitter2(v->path, use); }

CLRT_INLINE float3 transport_light_term(const TransportVertex* v, __global const Light* light,
                                        const LightSample* ls) {
  return v->sp.base * direct_term(POINT_MATERIAL(&v->sp), v->sp.n, v->sp.v, ls->to_light, ls->intensity);
}


/* The reflection and refraction rays of a hit; returns which of them exist (CLRT_SPAWN_*).
 * Total internal reflection sends the kt share along the reflection ray. With `glossy` the
 * reflection ray's direction is drawn from the normalised Phong lobe of the material's exponent
 * about the mirror direction (Cook et al. 1984), and a direction below the surface spawns none. */
CLRT_INLINE uint spawn_children(const Ray* ray, const ShadePoint* s, MaterialRef m,
                                float epsilon, bool glossy, Ray* reflected, Ray* refracted) {
  const float3 d = vload3(0, ray->dir);
  const float3 r = glossy ? sample_phong(s->n, s->v, m->shininess, jitter2(ray->path, CLRT_GLOSSY_DIRECTION))
                          : reflect_dir(d, s->n);
  float reflect_share = m->kr;
  const float eta = s->front ? 1.0f / m->ior : m->ior;
  const float cos_i = -dot3(d, s->n);
  const float k = 1.0f - refracted_sin2(cos_i, eta);
  const bool refracts = m->kt > 0.0f && k >= 0.0f;
  if (m->kt > 0.0f && !refracts) reflect_share += m->kt;
  uint spawned = 0u;
  if (reflect_share > 0.0f && (!glossy || dot3(r, s->ng) > 0.0f)) {
    *reflected = child_ray(ray, s, offset_origin(s->p, s->ng, r, epsilon), r, reflect_share,
                           CLRT_BRANCH_REFLECT, CLRT_RAY_REFLECTION);
    spawned |= CLRT_SPAWN_REFLECTION;
  }
  if (refracts) {
    const float3 t = refracted_dir(d, s->n, eta, cos_i, sqrt(k));
    *refracted = child_ray(ray, s, offset_origin(s->p, s->ng, t, epsilon), t, m->kt,
                           CLRT_BRANCH_REFRACT, CLRT_RAY_REFRACTION);
    spawned |= CLRT_SPAWN_REFRACTION;
  }
  return spawned;
}

/* `tracing`: trace mode (shadow rays and children) rather than cast mode (local terms only). */
CLRT_INLINE float3 whitted_step(const Ray* ray, const Hit* hit, __global const Material* materials,
                                TEXTURE_PARAMS, __global const Light* lights, __global const RenderParams* params,
                                bool tracing, uint owner, RaySink* sink) {
  if (hit->instance == CLRT_NO_HIT) return miss_colour(ray, lights, params);
  TransportVertex vertex;
  vertex.sp = shade_point(ray, hit, materials, TEXTURE_ARGS, params);
  vertex.path = ray->path;
  float3 c = ambient_colour(&vertex.sp, POINT_MATERIAL(&vertex.sp), params) + emitted(ray, hit, materials);
  gather_light_samples(&vertex, &vertex.sp, lights, params, tracing, owner, ray->time, sink, &c);
  if (!tracing || CLRT_RAY_DEPTH(*ray) >= params->max_depth) return c;
  Ray reflected, refracted;
  const uint spawned = spawn_children(ray, &vertex.sp, POINT_MATERIAL(&vertex.sp), params->epsilon,
                                      params->glossy != 0u, &reflected, &refracted);
  if (spawned & CLRT_SPAWN_REFRACTION) sink_child(sink, CLRT_SPAWN_REFRACTION, &refracted);
  if (spawned & CLRT_SPAWN_REFLECTION) sink_child(sink, CLRT_SPAWN_REFLECTION, &reflected);
  return c;
}

#endif
