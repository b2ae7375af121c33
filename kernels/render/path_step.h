/* The path-tracing transport model (path mode; docs/path-tracing.md, "The estimator"), with the
 * Whitted model's sink (render/ray_sink.h), so both integrators run it as they run that one: the
 * vertex's own emission is returned, its next-event shadow rays go to the sink in light-sample
 * order, and the one ray that continues the path goes to the sink as its reflection child (slot
 * 0). A ray's weight is the path's throughput, its pdf the density with which the lobes drew its
 * direction, its radiance_scale the refractions' product along the path. Each vertex draws its
 * scrambled Sobol samples (render/sobol.h), one pair per use, keyed by its ray's stream (path:
 * the pixel's, then one per bounce) and its depth, at its camera sample's index. */
#ifndef CLRT_RENDER_PATH_STEP_H
#define CLRT_RENDER_PATH_STEP_H

#include "light_loop.h"
#include "lobes.h"
#include "sobol.h"

/* The uses of a vertex's own pairs of random numbers: the direction, and the lobe choice (x)
 * with Russian roulette (y); light samples use 0, 1, ... and the camera jitter 0xffffffff, so
 * no two share numbers. */
#define CLRT_PATH_DIRECTION 0xfffffffeu
#define CLRT_PATH_CHOICE 0xfffffffdu

/* The first vertex depth at which Russian roulette may end a path. */
#define CLRT_PATH_ROULETTE_DEPTH 2u

/* The ray's pair of random numbers for `use` at its depth. */
CLRT_INLINE float2 path_sample(const Ray* ray, uint use) {
  return sobol_sample(sample_key(ray->path, CLRT_RAY_DEPTH(*ray), use), CLRT_SAMPLE_INDEX(*ray));
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

/* The radiance of the lights the ray passes through before t_end, times its throughput. */
CLRT_INLINE float3 crossed_emission(const Ray* ray, __global const Light* lights,
                                    __global const RenderParams* params, float t_end) {
  float3 e = (float3)(0.0f);
  const float3 o = vload3(0, ray->origin), d = vload3(0, ray->dir);
  for (uint l = 0; l < params->light_count; ++l) {
    __global const Light* light = &lights[l];
    const LightCrossing crossing = light_crossing(light, o, d, params->epsilon, t_end);
    if (crossing.t == INFINITY) continue;
    const float w = ray->pdf > 0.0f
                        ? power_heuristic(1.0f, ray->pdf, (float)light->samples * crossing.density)
                        : 1.0f;
    e += vload3(0, ray->weight) * crossing.radiance * w;
  }
  return e;
}

/* The multiple importance sampling weight of the glow a path met on a surface that the glow light
 * samples as well, against the density of that light's sample in the path's direction; a camera
 * ray, a delta lobe's ray (pdf 0) or a surface the light does not sample keeps all of it. */
CLRT_INLINE float glow_hit_weight(const Ray* ray, const Hit* hit, __global const Material* materials,
                                  __global const Light* lights, __global const RenderParams* params) {
  if (!(ray->pdf > 0.0f) || hit->glow == CLRT_NO_GLOW || params->glow_light == CLRT_NO_LIGHT)
    return 1.0f;
  __global const Light* light = &lights[params->glow_light];
  const float cos_light = fabs(dot3(xyz(hit->geometric_normal), vload3(0, ray->dir)));
  const float density = glow_light_density(light, hit->glow, vload3(0, ray->origin), hit->geometric_normal.w,
                                           cos_light, xyz(materials[hit->material].emission));
  return power_heuristic(1.0f, ray->pdf, (float)light->samples * density);
}

/* What a path that escapes brings: the background, or the environment's radiance along it,
 * weighed by MIS against the environment's samples in its direction where they sample it (not
 * for the camera's rays or a delta lobe's, pdf 0), times its throughput. */
CLRT_INLINE float3 escaped(const Ray* ray, __global const Light* lights, __global const RenderParams* params) {
  if (params->environment == CLRT_NO_LIGHT) return miss_colour(ray, lights, params);
  __global const Light* light = &lights[params->environment];
  const EnvironmentPlace place = environment_place(light, vload3(0, ray->dir));
  const float w = ray->pdf > 0.0f && params->environment < params->light_count
                      ? power_heuristic(1.0f, ray->pdf,
                                        (float)light->samples * environment_place_density(light, place))
                      : 1.0f;
  return vload3(0, ray->weight) * environment_place_radiance(light, place) * w;
}

struct TransportVertex {
  ShadePoint sp;
  PathLobes lobes;
  const Ray* ray;
};

CLRT_INLINE float2 transport_light_pair(const TransportVertex* v, uint use) { return path_sample(v->ray, use); }

/* What the light sample brings to the vertex through the smooth lobes, times the path's
 * throughput, before its shadow ray decides whether it arrives. */
CLRT_INLINE float3 transport_light_term(const TransportVertex* v, __global const Light* light,
                                        const LightSample* ls) {
  float pdf;
  const float3 f = smooth_lobes(&v->lobes, POINT_MATERIAL(&v->sp), v->sp.n, v->sp.v, ls->to_light, &pdf);
  float3 estimate = (float3)(0.0f);
  if (!all(f == (float3)(0.0f)) && ls->geometry != 0.0f) {
    /* A light that paths can hit as well shares this direction with the BSDF's samples. */
    const float w = ls->density > 0.0f ? power_heuristic((float)light->samples, ls->density, pdf) : 1.0f;
    estimate = f * dot3(v->sp.n, ls->to_light) * ls->intensity * (ls->geometry * w);
  }
  return vload3(0, v->ray->weight) * estimate;
}


CLRT_INLINE float3 path_step(const Ray* ray, const Hit* hit, __global const Material* materials,
                             TEXTURE_PARAMS, __global const Light* lights, __global const RenderParams* params,
                             uint owner, RaySink* sink) {
  const bool missed = hit->instance == CLRT_NO_HIT;
  float3 c = crossed_emission(ray, lights, params, missed ? INFINITY : hit->geometric_normal.w);
  if (missed) return c + escaped(ray, lights, params);
  c += emitted(ray, hit, materials) * glow_hit_weight(ray, hit, materials, lights, params);
  /* Past the depth cap a ray only gathers the light it meets: the cap vertex still draws a
   * direction, so that its next-event estimates' MIS weights have their other strategy, and the
   * light its mirror and glass lobes bring (which no shadow ray samples) is not lost. */
  if (CLRT_RAY_DEPTH(*ray) > params->max_depth) return c;
  TransportVertex vertex;
  vertex.sp = shade_point(ray, hit, materials, TEXTURE_ARGS, params);
  vertex.lobes = path_lobes(POINT_MATERIAL(&vertex.sp));
  vertex.ray = ray;
  if (has_smooth_lobes(&vertex.lobes))
    gather_light_samples(&vertex, &vertex.sp, lights, params, true, owner, ray->time, sink, &c);
  const float2 choice = path_sample(ray, CLRT_PATH_CHOICE);
  LobeSample s;
  float pdf;
  if (!sample_lobes(&vertex.lobes, POINT_MATERIAL(&vertex.sp), &vertex.sp, vload3(0, ray->dir),
                    path_sample(ray, CLRT_PATH_DIRECTION), choice.x, &s, &pdf))
    return c;
  float3 throughput = vload3(0, ray->weight) * s.weight;
  /* Roulette ignores the refractions' radiance scales (a camera ray's is 1), or a path in glass,
   * cut down to 1/ior^2 on the way in, would be rouletted and then multiplied by ior^2 on the way
   * out (pbrt-v4 does the same). */
  const float scale = ray->radiance_scale * s.radiance_scale;
  /* Russian roulette from the third vertex on: a path keeps going with probability min(1, the
   * square root of its largest channel), as Cycles does: gentler than the channel itself, whose
   * cuts added noise at equal samples. Sparing the first two keeps one-bounce light (and a
   * furnace test) free of roulette noise. */
  const float keep =
      CLRT_RAY_DEPTH(*ray) < CLRT_PATH_ROULETTE_DEPTH ? 1.0f : fmin(1.0f, sqrt(max3(throughput) / scale));
  if (keep < 1.0f) {
    if (!(choice.y < keep)) return c;
    throughput /= keep;
  }
  Ray next = child_ray(ray, &vertex.sp, offset_origin(vertex.sp.p, vertex.sp.ng, s.dir, params->epsilon), s.dir,
                       1.0f, CLRT_BRANCH_REFLECT, s.kind);
  next.radiance_scale = scale;
  vstore3(throughput, 0, next.weight);
  next.pdf = pdf;
  sink_child(sink, CLRT_SPAWN_REFLECTION, &next);
  return c;
}

#endif
