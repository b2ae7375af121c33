/* What both transport models need at a hit, shared by the wavefront's kernels and the
 * megakernel so that both compute every term with the same instructions:
 *   shade_point    the surface at a hit, seen from the ray, in its material with the textures
 *                  applied (render/texture.h);
 *   miss_colour    what a ray that hits nothing contributes;
 *   emitted        what a glowing surface sends back along the ray;
 *   offset_origin  where a secondary or shadow ray leaves the surface;
 *   shadow_ray_to  the shadow ray that decides whether a light sample's term counts;
 *   child_ray      a ray that continues from the hit. */
#ifndef CLRT_RENDER_SHADE_POINT_H
#define CLRT_RENDER_SHADE_POINT_H

#include "common.h"
#include "light_sample.h"
#include "lights/environment.h"
#include "optics.h"
#include "random.h"
#include "texture.h"

typedef struct ShadePoint {
  float3 p;     /* the hit point */
  float3 ng;    /* geometric normal, turned towards the incoming ray */
  float3 n;     /* shading normal, in ng's hemisphere */
  float3 v;     /* unit vector towards the ray's origin */
  float3 base;  /* the ray's weight times the material's local share */
  bool front;   /* the ray arrived on the side the surface's normal points to */
  float cone_width; /* the ray's cone's width there, where its children's cones start */
#if CLRT_SCENE_TEXTURED
  Material material; /* the hit's material, textured */
#else
  __global const Material* material; /* the hit's row of the material table */
#endif
} ShadePoint;

/* The material `s` shades with (MaterialRef). */
#if CLRT_SCENE_TEXTURED
#define POINT_MATERIAL(s) (&(s)->material)
#else
#define POINT_MATERIAL(s) ((s)->material)
#endif

/* The textures' tables, which every transport step passes on. */
#define TEXTURE_PARAMS __global const Texture* textures, __global const uint* texels
#define TEXTURE_ARGS textures, texels

CLRT_INLINE ShadePoint shade_point(const Ray* ray, const Hit* hit, __global const Material* materials,
                                   TEXTURE_PARAMS, __global const RenderParams* params) {
  ShadePoint s;
  s.cone_width = CLRT_SCENE_TEXTURED ? cone_width_at_hit(ray, hit, params->cone_spread) : 0.0f;
#if CLRT_SCENE_TEXTURED
  s.material = surface_material(materials, TEXTURE_ARGS, ray, hit, s.cone_width);
#else
  s.material = &materials[hit->material];
#endif
  const float3 d = vload3(0, ray->dir);
  s.p = vload3(0, ray->origin) + hit->geometric_normal.w * d;
  s.front = dot3(xyz(hit->geometric_normal), d) < 0.0f;
  s.ng = s.front ? xyz(hit->geometric_normal) : -xyz(hit->geometric_normal);
  /* Vertex normals may disagree with the winding (NFF patches, many OBJ exports): the shading
   * normal is first turned into the geometric normal's hemisphere, then faces the ray with it. */
  const float3 ns = xyz(hit->shading_normal);
  s.n = dot3(ns, s.ng) < 0.0f ? -ns : ns;
  s.v = -d;
  s.base = vload3(0, ray->weight) * local_share(POINT_MATERIAL(&s));
  return s;
}

/* The radiance a ray that hits nothing brings, times its weight: the environment's along its
 * direction, else the background. */
CLRT_INLINE float3 miss_colour(const Ray* ray, __global const Light* lights, __global const RenderParams* params) {
  const float3 radiance = params->environment == CLRT_NO_LIGHT
                              ? xyz(params->background)
                              : environment_radiance(&lights[params->environment], vload3(0, ray->dir));
  return vload3(0, ray->weight) * radiance;
}

/* The radiance the hit surface emits towards the ray's origin, times the ray's weight: its
 * material's emission on the front side (the side its normal points to), nothing behind. */
CLRT_INLINE float3 emitted(const Ray* ray, const Hit* hit, __global const Material* materials) {
  __global const Material* m = &materials[hit->material];
  if (m->emission.w == 0.0f || dot3(xyz(hit->geometric_normal), vload3(0, ray->dir)) >= 0.0f)
    return (float3)(0.0f);
  return vload3(0, ray->weight) * xyz(m->emission);
}

/* The point a secondary or shadow ray leaves from: p moved along the geometric normal, to the
 * side the ray leaves through, by epsilon or by 2^-18 of p's largest coordinate (32 of its float
 * steps), whichever is more. A hit point's error grows with its magnitude: at 1e10 a fixed 1e-4
 * left a quarter of a lit floor's shadow rays inside it, finding the floor (8 steps still left
 * some). Up to about 26, where the two are equal, every offset is epsilon's. */
CLRT_INLINE float3 offset_origin(float3 p, float3 ng, float3 dir, float epsilon) {
  const float reach = fmax(fmax(fabs(p.x), fabs(p.y)), fabs(p.z));
  const float offset = fmax(epsilon, reach * 0x1p-18f);
  return p + (dot3(ng, dir) >= 0.0f ? offset : -offset) * ng;
}

/* The shadow ray that carries `term` of light sample `ls` to the ray `owner`, whose time it
 * keeps. */
CLRT_INLINE ShadowRay shadow_ray_to(const ShadePoint* s, const LightSample* ls, float3 term, uint owner,
                                    float time, float epsilon) {
  const float3 origin = offset_origin(s->p, s->ng, ls->to_light, epsilon);
  const bool directional = ls->distance == INFINITY;
  ShadowRay sr;
  sr.origin = (f4)(origin, directional ? INFINITY : length3(ls->position - origin));
  sr.dir = as_f4(directional ? ls->to_light : normalize3(ls->position - origin));
  sr.contribution = as_f4(term);
  sr.owner = owner;
  sr.time = time;
  sr.pad[0] = sr.pad[1] = 0u;
  return sr;
}

/* A ray leaving the parent's hit `s` with `share` of its weight. It keeps its camera sample (that
 * sample's index, which path mode's Sobol samples need, and its time) and the refractions'
 * radiance scale so far, takes a stream of its own from its parent's and the branch, and starts
 * its cone where the parent's met the surface. */
CLRT_INLINE Ray child_ray(const Ray* parent, const ShadePoint* s, float3 origin, float3 dir,
                          float share, uint branch, uint kind) {
  Ray r;
  vstore3(origin, 0, r.origin);
  r.radiance_scale = parent->radiance_scale;
  vstore3(dir, 0, r.dir);
  r.sample_cone = CLRT_SAMPLE_CONE(CLRT_SAMPLE_INDEX(*parent), cone_code(s->cone_width));
  vstore3(vload3(0, parent->weight) * share, 0, r.weight);
  r.pdf = 0.0f;
  r.sample = parent->sample;
  r.depth_kind = CLRT_DEPTH_KIND(CLRT_RAY_DEPTH(*parent) + 1u, kind);
  r.path = child_path(parent->path, branch);
  r.time = parent->time;
  return r;
}

#endif
