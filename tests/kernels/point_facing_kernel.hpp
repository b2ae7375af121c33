// Device code the lobe tests share, put before their own kernels: the shading point they draw
// directions at.
#pragma once

namespace clrt::test {

inline const char* const kPointFacingKernelCode = R"CL(
#include "render/shade_point.h"

/* The front of a surface of `material` with normal n at the origin, seen from wo. */
CLRT_INLINE ShadePoint point_facing(float4 normal, float4 wo, __global const Material* material) {
  ShadePoint sp;
  sp.p = (float3)(0.0f);
  sp.ng = sp.n = normal.xyz;
  sp.v = wo.xyz;
  sp.base = (float3)(1.0f);
  sp.front = true;
  sp.cone_width = 0.0f;
  sp.material = *material;
  return sp;
}
)CL";

}  // namespace clrt::test
