/* The shade stage as device functions, shared by the wavefront's shade kernel and the
 * megakernel so that both compute every term with the same instructions:
 *   shade_point      the surface at a hit, seen from the ray;
 *   miss_colour      what a ray that hits nothing contributes;
 *   ambient_colour   the ambient term;
 *   light_term       what one light sample adds (zero: no shadow ray);
 *   shadow_ray_to    the shadow ray that decides whether a light sample's term counts;
 *   spawn_children   the reflection and refraction rays leaving the hit. */
#ifndef CLRT_RENDER_SHADE_POINT_H
#define CLRT_RENDER_SHADE_POINT_H

#include "common.h"
#include "lights.h"
#include "secondary.h"
#include "whitted.h"

typedef struct ShadePoint {
  float3 p;     /* the hit point */
  float3 ng;    /* geometric normal, turned towards the incoming ray */
  float3 n;     /* shading normal, in ng's hemisphere */
  float3 v;     /* unit vector towards the ray's origin */
  float3 base;  /* the ray's weight times the material's local share */
  bool front;   /* the ray arrived on the side the surface's normal points to */
  uint material;
} ShadePoint;

CLRT_INLINE ShadePoint shade_point(const Ray* ray, const Hit* hit, __global const Material* materials) {
  ShadePoint s;
  const float3 d = xyz(ray->dir);
  s.p = xyz(ray->origin) + hit->geometric_normal.w * d;
  s.front = dot3(xyz(hit->geometric_normal), d) < 0.0f;
  s.ng = s.front ? xyz(hit->geometric_normal) : -xyz(hit->geometric_normal);
  /* Vertex normals may disagree with the winding (NFF patches, many OBJ exports): the shading
   * normal is first turned into the geometric normal's hemisphere, then faces the ray with it. */
  const float3 ns = xyz(hit->shading_normal);
  s.n = dot3(ns, s.ng) < 0.0f ? -ns : ns;
  s.v = -d;
  s.material = hit->material;
  s.base = xyz(ray->weight) * local_share(&materials[hit->material]);
  return s;
}

CLRT_INLINE float3 miss_colour(const Ray* ray, __global const RenderParams* params) {
  return xyz(ray->weight) * xyz(params->background);
}

CLRT_INLINE float3 ambient_colour(const ShadePoint* s, __global const Material* materials,
                             __global const RenderParams* params) {
  __global const Material* m = &materials[s->material];
  return s->base * m->ka * xyz(params->ambient) * xyz(m->color);
}

/* The term sample j of `light` adds at s, and the sample in *sample. A zero term (N.L <= 0,
 * outside a spot's cone, kd = ks = 0) sends no shadow ray: it could not change the image. The
 * callers walk lights in table order and each light's samples in order, in plain counted loops
 * (a resumable cursor over both, tried first, ran forever now and then on Intel's CPU runtime). */
CLRT_INLINE float3 light_term(const ShadePoint* s, __global const Material* materials,
                              __global const Light* light, uint j, uint path, LightSample* sample) {
  const float2 u = light_is_sampled(light) ? jitter2(path, light->first_sample + j) : (float2)(0.0f);
  *sample = sample_light(light, j, s->p, u);
  return s->base * direct_term(&materials[s->material], s->n, s->v, sample->to_light,
                               sample->intensity);
}

/* The point a secondary or shadow ray leaves from: p moved by epsilon along the geometric
 * normal, to the side the ray leaves through. */
CLRT_INLINE float3 offset_origin(float3 p, float3 ng, float3 dir, float epsilon) {
  return p + (dot3(ng, dir) >= 0.0f ? epsilon : -epsilon) * ng;
}

/* The shadow ray that carries `term` of light sample `ls` to the ray `owner`. */
CLRT_INLINE ShadowRay shadow_ray_to(const ShadePoint* s, const LightSample* ls, float3 term, uint owner,
                               float epsilon) {
  const float3 origin = offset_origin(s->p, s->ng, ls->to_light, epsilon);
  const bool directional = ls->distance == INFINITY;
  ShadowRay sr;
  sr.origin = (f4)(origin, directional ? INFINITY : length3(ls->position - origin));
  sr.dir = as_f4(directional ? ls->to_light : normalize3(ls->position - origin));
  sr.contribution = as_f4(term);
  sr.owner = owner;
  sr.pad[0] = sr.pad[1] = sr.pad[2] = 0u;
  return sr;
}

#define CLRT_SPAWN_REFLECTION 1u
#define CLRT_SPAWN_REFRACTION 2u

/* The reflection and refraction rays of a hit; returns which of them exist (CLRT_SPAWN_*).
 * Total internal reflection sends the kt share along the reflection ray. */
CLRT_INLINE uint spawn_children(const Ray* ray, const ShadePoint* s, __global const Material* materials,
                           __global const RenderParams* params, Ray* reflected, Ray* refracted) {
  __global const Material* m = &materials[s->material];
  const float3 d = xyz(ray->dir);
  const float3 r = reflect_dir(d, s->n);
  float reflect_share = m->kr;
  float3 t;
  const float eta = s->front ? 1.0f / m->ior : m->ior;
  const bool refracts = m->kt > 0.0f && refract_dir(d, s->n, eta, &t);
  if (m->kt > 0.0f && !refracts) reflect_share += m->kt;
  uint spawned = 0u;
  if (reflect_share > 0.0f) {
    *reflected = child_ray(ray, offset_origin(s->p, s->ng, r, params->epsilon), r, reflect_share,
                           CLRT_BRANCH_REFLECT, CLRT_RAY_REFLECTION);
    spawned |= CLRT_SPAWN_REFLECTION;
  }
  if (refracts) {
    *refracted = child_ray(ray, offset_origin(s->p, s->ng, t, params->epsilon), t, m->kt,
                           CLRT_BRANCH_REFRACT, CLRT_RAY_REFRACTION);
    spawned |= CLRT_SPAWN_REFRACTION;
  }
  return spawned;
}

#endif
