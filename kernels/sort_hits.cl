/* classify_hits: the shading class of each ray of a chunk, so that the wavefront can shade it
 * class by class (Laine, Karras and Aila, "Megakernels Considered Harmful", HPG 2013: one queue
 * per material kind), each launch running one kind of work with no divergence between its
 * work-items: rays that missed, hits on surfaces with only the local (smooth) terms, and hits
 * on mirrors and glass, which also spawn rays.
 * In: hits [first, first + count). Out: indices[j] = (first + j, 0, 0, 0) and, for every class
 * k, flags[k * stride + j] = 1 when ray first + j is of class k, else 0: one launch flags all
 * the classes, and the wavefront compacts each class's flagged indices into its shading order
 * (src/render/integrators/wavefront.cpp). */
#include "render/common.h"

/* The classes, 0 to CLRT_SHADE_CLASSES - 1 (kernels/shared/ray.h). */
#define CLRT_SHADE_MISS 0u
#define CLRT_SHADE_LOCAL 1u
#define CLRT_SHADE_SPECULAR 2u

__kernel void classify_hits(__global const Material* materials, __global const Hit* hits,
                            uint first, uint count, uint stride, __global uint4* indices,
                            __global uint* flags) {
  const uint j = get_global_id(0);
  if (j >= count) return;
  const Hit hit = hits[first + j];
  uint c = CLRT_SHADE_MISS;
  if (hit.instance != CLRT_NO_HIT) {
    __global const Material* m = &materials[hit.material];
    c = m->kr > 0.0f || m->kt > 0.0f ? CLRT_SHADE_SPECULAR : CLRT_SHADE_LOCAL;
  }
  indices[j] = (uint4)(first + j, 0u, 0u, 0u);
  for (uint k = 0; k < CLRT_SHADE_CLASSES; ++k) flags[k * stride + j] = c == k ? 1u : 0u;
}
