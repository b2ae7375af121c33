/* Helpers every stage uses. FP_CONTRACT is off so that no compiler fuses a*b+c differently in
 * different kernels or devices: the same sum must give the same bits wherever it is computed
 * (cast and trace mode agree where no shadow or secondary ray acts). */
#ifndef CLRT_RENDER_COMMON_H
#define CLRT_RENDER_COMMON_H

#pragma OPENCL FP_CONTRACT OFF

#include "../shared/ray.h"
#include "../shared/scene.h"

inline float3 xyz(f4 v) { return v.xyz; }
inline f4 as_f4(float3 v) { return (f4)(v, 0.0f); }

#endif
