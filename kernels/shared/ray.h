/* The records that flow through the wavefront queues. */
#ifndef CLRT_SHARED_RAY_H
#define CLRT_SHARED_RAY_H
#include "common.h"

CLRT_SHARED_BEGIN

#define CLRT_NO_HIT 0xffffffffu

/* What produced a ray; counted separately by --stats. Queues hold the first three kinds;
 * shadow rays have their own records. CLRT_RAY_KINDS sizes every per-kind table. */
#define CLRT_RAY_CAMERA 0u
#define CLRT_RAY_REFLECTION 1u
#define CLRT_RAY_REFRACTION 2u
#define CLRT_RAY_SHADOW 3u
#define CLRT_RAY_KINDS 4u

/* Ray.depth_kind packs a queue ray's depth and kind in one word, so that the record has room
 * for its time. */
#define CLRT_DEPTH_KIND(depth, kind) (((depth) << 2) | (kind))
#define CLRT_RAY_DEPTH(ray) ((ray).depth_kind >> 2)
#define CLRT_RAY_KIND(ray) ((ray).depth_kind & 3u)

/* Ray.sample_cone's halves. A cone's width w > 0 is kept as 32768 + 256 log2(w), rounded and
 * held to [1, 65535] (a relative step of 0.27%, widths from 2^-128 to 2^128); 0 is width 0, a
 * camera ray's. */
#define CLRT_SAMPLE_INDEX(ray) ((ray).sample_cone & 0xffffu)
#define CLRT_CONE_CODE(ray) ((ray).sample_cone >> 16)
#define CLRT_SAMPLE_CONE(sample_index, cone_code) ((sample_index) | ((cone_code) << 16))

/* Child-ray slots per ray of a queue: its reflection (slot 0) and its refraction (slot 1). */
#define CLRT_CHILD_SLOTS 2u

/* Shading classes when the wavefront shades class by class (kernels/sort_hits.cl). */
#define CLRT_SHADE_CLASSES 3u

/* A camera, reflection or refraction ray. Queues are kept sorted by `sample` (camera rays are
 * generated in sample order and compaction is stable), which is what lets contributions be
 * summed per sample in a fixed order without atomics. The vectors are float triples (read with
 * vload3), so that the record keeps 64 bytes with path mode's three numbers named beside them. */
typedef struct Ray {
  float origin[3];      /* already offset from the surface it leaves */
  float radiance_scale; /* path mode: the product of the refractions' radiance scales along the
                         * path (render/path_step.h), which Russian roulette leaves out; 1 for a
                         * camera ray */
  float dir[3];         /* unit direction */
  u32 sample_cone;      /* low 16 bits: the camera sample's index within its pixel, which path
                         * mode's Sobol samples need (every ray of a sample keeps it; there are
                         * at most 65536); high 16 bits: the width of the ray's cone where it
                         * starts, which picks the textures' filter where it lands
                         * (render/texture.h), as CLRT_CONE_CODE */
  float weight[3];      /* rgb share of the sample's colour this ray carries (a path's
                         * throughput) */
  float pdf;            /* path mode: the solid-angle density its direction was drawn with, for
                         * multiple importance sampling where it crosses a light; 0 from the
                         * camera and after a mirror or glass bounce */
  u32 sample;           /* camera sample index within the current wave */
  u32 depth_kind;       /* depth << 2 | kind: depth 0 for camera rays, kind CLRT_RAY_* (one of
                         * the first three); CLRT_RAY_DEPTH, CLRT_RAY_KIND and CLRT_DEPTH_KIND */
  u32 path;             /* seeds this ray's random numbers: the hash of the branch choices since
                         * the camera ray, which starts from the camera sample's stream (in path
                         * mode the pixel's) */
  float time;           /* the camera sample's time within the shutter, which every ray of the
                         * sample keeps: moving instances are where they are at that time */
} Ray;
CLRT_CHECK_SIZE(Ray, 64);

/* The closest hit of ray i of the queue is hit i. */
typedef struct Hit {
  f4 geometric_normal; /* world space, unit, as the surface defines it (not flipped); w = t */
  f4 shading_normal;   /* world space, unit; interpolated vertex normal on meshes; w unused */
  u32 instance;        /* CLRT_NO_HIT on a miss */
  u32 primitive;       /* triangle index for meshes, 0 for canonical shapes */
  u32 material;        /* index into the material table, resolved by the intersector */
  u32 glow;            /* its instance's Instance.glow */
  float u, v;          /* texture coordinates (docs/scene-format.md#texture-coordinates) */
  float uv_scale;      /* world length per unit of (u, v) about the hit: the square root of the
                          world area a unit of uv area covers there (0 where it vanishes) */
  float pad;
} Hit;
CLRT_CHECK_SIZE(Hit, 64);

/* A shadow ray towards one light sample, carrying the light's contribution to its owner ray
 * if nothing blocks it. */
typedef struct ShadowRay {
  f4 origin;       /* xyz offset origin; w = tmax (distance to the light sample, INFINITY when directional) */
  f4 dir;          /* xyz unit direction towards the light; w unused */
  f4 contribution; /* rgb added to the owner ray's colour when unblocked; w unused */
  u32 owner;       /* index of the shaded ray in the current queue */
  float time;      /* its owner's Ray.time */
  u32 pad[2];
} ShadowRay;
CLRT_CHECK_SIZE(ShadowRay, 64);

CLRT_SHARED_END

#endif
