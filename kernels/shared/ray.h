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

/* Child-ray slots per ray of a queue: its reflection (slot 0) and its refraction (slot 1). */
#define CLRT_CHILD_SLOTS 2u

/* Shading classes when the wavefront shades class by class (kernels/sort_hits.cl). */
#define CLRT_SHADE_CLASSES 3u

/* A camera, reflection or refraction ray. Queues are kept sorted by `sample` (camera rays are
 * generated in sample order and compaction is stable), which is what lets contributions be
 * summed per sample in a fixed order without atomics. */
typedef struct Ray {
  f4 origin;  /* xyz, already offset from the surface it leaves; w: in path mode, see
               * render/path_step.h, else 0 */
  f4 dir;     /* xyz unit direction; w: in path mode the camera sample's index within its pixel
               * (exact as a float: at most 65535), which its Sobol samples need, else 0 */
  f4 weight;  /* rgb share of the sample's colour this ray carries; w: in path mode the density
               * its direction was drawn with (render/path_step.h), else 0 */
  u32 sample; /* camera sample index within the current wave */
  u32 depth;  /* 0 for camera rays */
  u32 path;   /* seeds this ray's random numbers: the hash of the branch choices since the camera
               * ray, which starts from the camera sample's stream (in path mode the pixel's) */
  u32 kind;   /* CLRT_RAY_* */
} Ray;
CLRT_CHECK_SIZE(Ray, 64);

/* The closest hit of ray i of the queue is hit i. */
typedef struct Hit {
  f4 geometric_normal; /* world space, unit, as the surface defines it (not flipped); w = t */
  f4 shading_normal;   /* world space, unit; interpolated vertex normal on meshes; w unused */
  u32 instance;        /* CLRT_NO_HIT on a miss */
  u32 primitive;       /* triangle index for meshes, 0 for canonical shapes */
  u32 material;        /* index into the material table, resolved by the intersector */
  u32 pad;
} Hit;
CLRT_CHECK_SIZE(Hit, 48);

/* A shadow ray towards one light sample, carrying the light's contribution to its owner ray
 * if nothing blocks it. */
typedef struct ShadowRay {
  f4 origin;       /* xyz offset origin; w = tmax (distance to the light sample, INFINITY when directional) */
  f4 dir;          /* xyz unit direction towards the light; w unused */
  f4 contribution; /* rgb added to the owner ray's colour when unblocked; w unused */
  u32 owner;       /* index of the shaded ray in the current queue */
  u32 pad[3];
} ShadowRay;
CLRT_CHECK_SIZE(ShadowRay, 64);

CLRT_SHARED_END

#endif
