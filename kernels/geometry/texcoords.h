/* Texture coordinates (u, v) of the canonical shapes and of triangles, and how large a unit of
 * (u, v) is in world space about the hit, which the texture filter needs
 * (docs/scene-format.md#texture-coordinates). Each shape's (u, v) runs to the right and up as
 * its outside is seen with +y up (with -z up on a top face, +z up on a bottom one), so an image
 * shows the right way round. */
#ifndef CLRT_GEOMETRY_TEXCOORDS_H
#define CLRT_GEOMETRY_TEXCOORDS_H

#include "math/exact.h"
#include "geometry/motion.h"
#include "shared/scene.h"

/* (u, v) and the object-space area a unit of (u, v) area covers there. */
typedef struct SurfaceCoords {
  float u, v;
  float area;
} SurfaceCoords;

CLRT_INLINE SurfaceCoords surface_coords(float u, float v, float area) {
  SurfaceCoords c;
  c.u = u;
  c.v = v;
  c.area = area;
  return c;
}

/* The angle about the y axis in turns, 0.5 on +z, rising towards +x (to the right of a viewer
 * on +z), the seam on -z. */
CLRT_INLINE float turns_about_y(float3 p) { return 0.5f + exact_atan2(p.x, p.z) * 0.159154937f; }

/* A flat face of the box [-1, 1]^3 (or a cap) across its axis `n` (outward, one component +-1):
 * its square maps onto [0, 1]^2. */
CLRT_INLINE SurfaceCoords face_coords(float3 p, float3 n) {
  float u, v;
  if (n.y != 0.0f) {
    u = 0.5f * (p.x + 1.0f);
    v = 0.5f * (n.y > 0.0f ? 1.0f - p.z : p.z + 1.0f);
  } else if (n.x != 0.0f) {
    u = 0.5f * (n.x > 0.0f ? 1.0f - p.z : p.z + 1.0f);
    v = 0.5f * (p.y + 1.0f);
  } else {
    u = 0.5f * (n.z > 0.0f ? p.x + 1.0f : 1.0f - p.x);
    v = 0.5f * (p.y + 1.0f);
  }
  return surface_coords(u, v, 4.0f);
}

/* Canonical shape `shape` at object point p with outward normal n (not unit). The sphere takes
 * u around y and v from the south pole (0) to the north (1); a plane u = x, v = -z; the side of
 * a cylinder or cone u around y and v = (y + 1) / 2, their caps and the cube's faces a square
 * each. */
CLRT_INLINE SurfaceCoords shape_coords(u32 shape, float cone_r0, float cone_r1, float3 p, float3 n) {
  switch (shape) {
    case CLRT_SHAPE_SPHERE: {
      const float ring = sqrt(p.x * p.x + p.z * p.z);
      const float v = 1.0f - exact_atan2(ring, p.y) * 0.318309873f;
      /* |dp/du| |dp/dv| = 2 pi sin(theta) * pi */
      return surface_coords(turns_about_y(p), v, 19.7392082f * ring);
    }
    case CLRT_SHAPE_PLANE: return surface_coords(p.x, -p.z, 1.0f);
    case CLRT_SHAPE_CUBE: {
      const float3 a = fabs(n);
      const float3 axis = a.x >= a.y && a.x >= a.z ? (float3)(n.x > 0.0f ? 1.0f : -1.0f, 0.0f, 0.0f)
                          : a.y >= a.z ? (float3)(0.0f, n.y > 0.0f ? 1.0f : -1.0f, 0.0f)
                                       : (float3)(0.0f, 0.0f, n.z > 0.0f ? 1.0f : -1.0f);
      return face_coords(p, axis);
    }
    default: { /* cylinder, cone */
      if (n.x == 0.0f && n.z == 0.0f) return face_coords(p, (float3)(0.0f, n.y, 0.0f));
      const float r0 = shape == CLRT_SHAPE_CONE ? cone_r0 : 1.0f;
      const float r1 = shape == CLRT_SHAPE_CONE ? cone_r1 : 1.0f;
      const float m = 0.5f * (r1 - r0);
      /* |dp/du| = 2 pi R(y), |dp/dv| = 2 sqrt(1 + m^2) along the slant */
      return surface_coords(turns_about_y(p), 0.5f * (p.y + 1.0f),
                            12.5663706f * sqrt(p.x * p.x + p.z * p.z) * sqrt(1.0f + m * m));
    }
  }
}

/* A triangle's (u, v) at barycentrics b1 (weight of corner 1) and b2, from its corners'
 * coordinates (the mesh's rows, or (0, 0), (1, 0), (0, 1)), and the object area of a unit of
 * (u, v) area: its area over the area of its corners' (u, v) triangle (0 when that vanishes). */
CLRT_INLINE SurfaceCoords triangle_coords(__global const TriangleTexcoords* texcoords, u32 row,
                                          float b1, float b2, float3 edge1, float3 edge2) {
  float uv[6] = {0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f};
  if (row != CLRT_NO_TEXCOORDS)
    for (int i = 0; i < 6; ++i) uv[i] = texcoords[row].uv[i];
  const float b0 = 1.0f - b1 - b2;
  const float u = b0 * uv[0] + b1 * uv[2] + b2 * uv[4];
  const float v = b0 * uv[1] + b1 * uv[3] + b2 * uv[5];
  const float uv_area = fabs((uv[2] - uv[0]) * (uv[5] - uv[1]) - (uv[4] - uv[0]) * (uv[3] - uv[1]));
  const float area = length3(cross3(edge1, edge2));
  return surface_coords(u, v, uv_area > 0.0f ? area / uv_area : 0.0f);
}

/* The world length of a unit of (u, v) about a point whose object-space unit of uv area covers
 * `area` with unit normal n: world areas are object areas times |det M| |M^-T n|. */
CLRT_INLINE float world_uv_scale(const InstanceFrame* f, float area, float3 n) {
  const float4 nn = (float4)(n, 0.0f);
  const float3 m = (float3)(dot4(f->normal_to_world[0], nn), dot4(f->normal_to_world[1], nn),
                            dot4(f->normal_to_world[2], nn));
  const float det_inverse =
      dot3(f->to_object[0].xyz, cross3(f->to_object[1].xyz, f->to_object[2].xyz));
  return sqrt(area * length3(m) / fabs(det_inverse));
}

#endif
