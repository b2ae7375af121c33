/* One path-tracing vertex (docs/path-tracing.md, "The estimator"), the counterpart of the
 * Whitted step with the same sink (render/whitted_sink.h), so both integrators run it as they
 * run that one: the vertex's own emission is returned, its next-event shadow rays go to the
 * sink in light-sample order, and the one ray that continues the path goes to the sink as its
 * reflection child (slot 0). A ray's weight is the path's throughput; weight.w is the
 * solid-angle density with which the smooth lobes drew its direction (0 from the camera and
 * after a mirror or glass bounce), which multiple importance sampling needs where the ray
 * crosses an area light; origin.w (after the camera ray) is the product of the refractions'
 * radiance scales along the path, which Russian roulette leaves out. Each vertex draws its
 * scrambled Sobol samples (render/sobol.h), one pair per use, keyed by its ray's stream (path:
 * the pixel's, then one per bounce) and its depth, at its camera sample's index (dir.w). */
#ifndef CLRT_RENDER_PATH_STEP_H
#define CLRT_RENDER_PATH_STEP_H

#include "path_bsdf.h"
#include "shade_point.h"
#include "sobol.h"
#include "whitted_sink.h"

/* The uses of a vertex's own pairs of random numbers: the direction, and the lobe choice (x)
 * with Russian roulette (y); light samples use 0, 1, ... and the camera jitter 0xffffffff, so
 * no two share numbers. */
#define CLRT_PATH_DIRECTION 0xfffffffeu
#define CLRT_PATH_CHOICE 0xfffffffdu

/* The first vertex depth at which Russian roulette may end a path. */
#define CLRT_PATH_ROULETTE_DEPTH 2u

/* The ray's pair of random numbers for `use` at its depth. */
CLRT_INLINE float2 path_sample(const Ray* ray, uint use) {
  return sobol_sample(sample_key(ray->path, ray->depth, use), (uint)ray->dir.w);
}

/* Where o + t d with t in (tmin, tmax) crosses the parallelogram of area light `light`: t, or
 * INFINITY when it does not; *cos_light is |cos| between d and the light's normal and *area
 * the light's area. */
CLRT_INLINE float area_light_crossing(__global const Light* light, float3 o, float3 d, float tmin,
                                      float tmax, float* cos_light, float* area) {
  const float3 u = xyz(light->edge_u), v = xyz(light->edge_v);
  const float3 normal = cross3(u, v); /* its length is the area */
  const float facing = dot3(normal, d);
  if (facing == 0.0f) return INFINITY;
  const float t = dot3(normal, xyz(light->position) - o) / facing;
  if (!(t > tmin && t < tmax)) return INFINITY;
  const float3 p = o + t * d - xyz(light->position);
  const float n2 = dot3(normal, normal);
  const float a = dot3(cross3(p, v), normal) / n2, b = dot3(cross3(u, p), normal) / n2;
  if (!(a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f)) return INFINITY;
  *area = sqrt(n2);
  *cos_light = fabs(facing) / *area;
  return t;
}

/* The power heuristic for `count` draws from density `pdf` against one from `other`, as a ratio
 * so that densities whose squares overflow a float (a light sample on a plane millions of units
 * away) still give a weight. */
CLRT_INLINE float power_heuristic(float count, float pdf, float other) {
  const float a = count * pdf;
  if (!(a > 0.0f)) return 0.0f;
  const float r = other / a;
  return 1.0f / (1.0f + r * r);
}

/* The radiance of the area lights the ray passes through before t_end, times its throughput. */
CLRT_INLINE float3 crossed_emission(const Ray* ray, __global const Light* lights,
                                    __global const RenderParams* params, float t_end) {
  float3 e = (float3)(0.0f);
  const float3 o = xyz(ray->origin), d = xyz(ray->dir);
  for (uint l = 0; l < params->light_count; ++l) {
    __global const Light* light = &lights[l];
    if (light->kind != CLRT_LIGHT_AREA) continue;
    float cos_light, area;
    const float t = area_light_crossing(light, o, d, params->epsilon, t_end, &cos_light, &area);
    if (t == INFINITY) continue;
    const float bsdf_pdf = ray->weight.w;
    const float light_pdf = t * t / (cos_light * area);
    const float w =
        bsdf_pdf > 0.0f ? power_heuristic(1.0f, bsdf_pdf, (float)light->samples * light_pdf) : 1.0f;
    e += xyz(ray->weight) * xyz(light->color) * w;
  }
  return e;
}

/* What light sample j of `light` brings to the vertex through the smooth lobes, before its
 * shadow ray decides whether it arrives. */
CLRT_INLINE float3 light_estimate(const ShadePoint* sp, const PathLobes* lobes,
                                  __global const Light* light, const LightSample* ls) {
  float pdf;
  const float3 f = smooth_lobes(lobes, sp->n, sp->v, ls->to_light, &pdf);
  if (all(f == (float3)(0.0f)) || ls->geometry == 0.0f) return (float3)(0.0f);
  /* A light that paths can hit as well shares this direction with the BSDF's samples. */
  const float w = ls->density > 0.0f ? power_heuristic((float)light->samples, ls->density, pdf) : 1.0f;
  return f * dot3(sp->n, ls->to_light) * ls->intensity * (ls->geometry * w);
}

/* The direction the path continues in, drawn with the pair u for the direction and x in [0, 1)
 * for the lobe: its weight f cos / pdf (with the lobe choice), the density for MIS, the ray kind
 * and the refraction's radiance scale within the weight (1 unless it refracts); false when the
 * path ends here. */
CLRT_INLINE bool continue_path(const Ray* ray, const ShadePoint* sp, const PathLobes* lobes,
                               __global const Material* m, float2 u, float x, float3* dir,
                               float3* weight, float* pdf, uint* kind, float* radiance_scale) {
  const float3 d = xyz(ray->dir);
  *pdf = 0.0f;
  *kind = CLRT_RAY_REFLECTION;
  *radiance_scale = 1.0f;
  const float smooth = lobes->p_diffuse + lobes->p_glossy;
  if (x < smooth) {
    *dir = x < lobes->p_diffuse ? sample_cosine(sp->n, u) : sample_phong(sp->n, sp->v, lobes->exponent, u);
    const float3 f = smooth_lobes(lobes, sp->n, sp->v, *dir, pdf);
    if (!(*pdf > 0.0f)) return false;
    *weight = f * (dot3(sp->n, *dir) / *pdf);
    return true;
  }
  if (x < smooth + lobes->p_mirror) {
    *dir = reflect_dir(d, sp->n);
    *weight = (float3)(lobes->mirror / lobes->p_mirror);
    return true;
  }
  if (!(lobes->p_glass > 0.0f)) return false;
  /* The rest of x chooses between reflection and refraction. */
  const float y = (x - smooth - lobes->p_mirror) / lobes->p_glass;
  const float cos_i = -dot3(d, sp->n);
  const float eta = sp->front ? 1.0f / m->ior : m->ior;
  float cos_t;
  const float f = fresnel_dielectric(cos_i, eta, &cos_t);
  float share = lobes->glass / lobes->p_glass;
  if (y < f) {
    *dir = reflect_dir(d, sp->n);
  } else {
    *dir = normalize3(eta * d + (eta * cos_i - cos_t) * sp->n);
    *radiance_scale = eta * eta; /* radiance compressed into the denser medium's smaller solid angle */
    share *= *radiance_scale;
    *kind = CLRT_RAY_REFRACTION;
  }
  *weight = (float3)(share);
  return true;
}

CLRT_INLINE float3 path_step(const Ray* ray, const Hit* hit, __global const Material* materials,
                             __global const Light* lights, __global const RenderParams* params,
                             uint owner, WhittedSink* sink) {
  const bool missed = hit->instance == CLRT_NO_HIT;
  float3 c = crossed_emission(ray, lights, params, missed ? INFINITY : hit->geometric_normal.w);
  if (missed) return c + miss_colour(ray, params);
  /* Past the depth cap a ray only gathers the light it meets: the cap vertex still draws a
   * direction, so that its next-event estimates' MIS weights have their other strategy, and the
   * light its mirror and glass lobes bring (which no shadow ray samples) is not lost. */
  if (ray->depth > params->max_depth) return c;
  const ShadePoint sp = shade_point(ray, hit, materials);
  __global const Material* m = &materials[sp.material];
  const PathLobes lobes = path_lobes(m);
  const float3 beta = xyz(ray->weight);
  if (lobes.p_diffuse + lobes.p_glossy > 0.0f) {
    for (uint l = 0; l < params->light_count; ++l) {
      __global const Light* light = &lights[l];
      for (uint j = 0; j < light->samples; ++j) {
        const uint use = light->first_sample + j;
        const LightSample ls = sample_light(light, j, sp.p,
                                            light_is_sampled(light) ? path_sample(ray, use) : (float2)(0.0f));
        const float3 term = beta * light_estimate(&sp, &lobes, light, &ls);
        if (all(term == (float3)(0.0f))) continue;
        const ShadowRay sr = shadow_ray_to(&sp, &ls, term, owner, params->epsilon);
        sink_shadow(sink, light->first_sample + j, &sr, &c);
      }
    }
  }
  float3 dir, weight;
  float pdf, radiance_scale;
  uint kind;
  const float2 choice = path_sample(ray, CLRT_PATH_CHOICE);
  if (!continue_path(ray, &sp, &lobes, m, path_sample(ray, CLRT_PATH_DIRECTION), choice.x, &dir,
                     &weight, &pdf, &kind, &radiance_scale))
    return c;
  float3 throughput = beta * weight;
  /* The refractions' radiance scales so far (origin.w of a path's rays; a camera ray's is 1):
   * roulette ignores them, or a path in glass, cut down to 1/ior^2 on the way in, would be
   * rouletted and then multiplied by ior^2 on the way out (pbrt-v4 does the same). */
  const float scale = (ray->depth == 0u ? 1.0f : ray->origin.w) * radiance_scale;
  /* Russian roulette from the third vertex on: a path keeps going with probability min(1, the
   * square root of its largest channel), as Cycles does: gentler than the channel itself, whose
   * cuts added noise at equal samples. Sparing the first two keeps one-bounce light (and a
   * furnace test) free of roulette noise. */
  const float keep =
      ray->depth < CLRT_PATH_ROULETTE_DEPTH ? 1.0f : fmin(1.0f, sqrt(max3(throughput) / scale));
  if (keep < 1.0f) {
    if (!(choice.y < keep)) return c;
    throughput /= keep;
  }
  Ray next = child_ray(ray, offset_origin(sp.p, sp.ng, dir, params->epsilon), dir, 1.0f,
                       CLRT_BRANCH_REFLECT, kind);
  next.origin.w = scale;
  next.weight = (f4)(throughput, pdf);
  sink_child(sink, CLRT_SPAWN_REFLECTION, &next);
  return c;
}

#endif
