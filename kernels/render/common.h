/* Helpers every stage uses. */
#ifndef CLRT_RENDER_COMMON_H
#define CLRT_RENDER_COMMON_H

#include "../shared/ray.h"
#include "../shared/scene.h"
#include "../math/exact.h"

CLRT_INLINE float3 xyz(f4 v) { return v.xyz; }
CLRT_INLINE f4 as_f4(float3 v) { return (f4)(v, 0.0f); }
CLRT_INLINE float max3(float3 v) { return fmax(v.x, fmax(v.y, v.z)); }
CLRT_INLINE float mean3(float3 v) { return (v.x + v.y + v.z) * (1.0f / 3.0f); }

/* The material a shading point reads. A program for a scene with textures shades with a private
 * copy its textures have changed (render/texture.h); one without reads the table in place, as
 * copying it cost scenes without textures 2-3% of their render on PoCL. */
#if CLRT_SCENE_TEXTURED
typedef const Material* MaterialRef;
#else
typedef __global const Material* MaterialRef;
#endif

#endif
