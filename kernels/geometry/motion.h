/* A moving instance's pose at a ray's time (kernels/shared/scene.h, InstanceMotion).
 *
 * M(t) = T(t) R(t) S(t), so M(t)^-1 = S(t)^-1 R(t)^T (p - T(t)) and the normals' matrix
 * (M^-1)^T = R S^-1 (S is symmetric). Everything is spelled out in +, -, *, / and the exact
 * sine of math/exact.h, so a moving object is in the same place on every implementation. */
#ifndef CLRT_GEOMETRY_MOTION_H
#define CLRT_GEOMETRY_MOTION_H

#include "math/exact.h"
#include "shared/scene.h"

/* Whether an instance's or mesh leaf's `motion` field names a motion in this program. */
CLRT_INLINE bool has_motion(u32 motion) { return CLRT_SCENE_MOVES && motion != CLRT_NO_MOTION; }

/* An instance's maps at one time: rows 0..2 of M^-1 and of (M^-1)^T, as Instance holds them. */
typedef struct InstanceFrame {
  float4 to_object[3];
  float4 normal_to_world[3];
} InstanceFrame;

/* Rotation matrix rows of the quaternion q (x, y, z, w), which need not be of unit length. */
CLRT_INLINE void quaternion_rows(float4 q, float3* r0, float3* r1, float3* r2) {
  const float k = 2.0f / dot4(q, q);
  const float xx = k * q.x * q.x, yy = k * q.y * q.y, zz = k * q.z * q.z;
  const float xy = k * q.x * q.y, xz = k * q.x * q.z, yz = k * q.y * q.z;
  const float wx = k * q.w * q.x, wy = k * q.w * q.y, wz = k * q.w * q.z;
  *r0 = (float3)(1.0f - (yy + zz), xy - wz, xz + wy);
  *r1 = (float3)(xy + wz, 1.0f - (xx + zz), yz - wx);
  *r2 = (float3)(xz - wy, yz + wx, 1.0f - (xx + yy));
}

/* The pose of motion m at `time`, clamped to [0, 1]. */
CLRT_INLINE InstanceFrame motion_frame(__global const InstanceMotion* m, float time) {
  const float t = fmin(fmax(time, 0.0f), 1.0f), s = 1.0f - t;
  const float3 translation = s * m->translation[0].xyz + t * m->translation[1].xyz;
  float a = s, b = t; /* slerp's weights; linear ones when the rotations are equal */
  if (m->angle_turns > 0.0f) {
    float sa, ca, sb, cb;
    sincos_turns(s * m->angle_turns, &sa, &ca);
    sincos_turns(t * m->angle_turns, &sb, &cb);
    a = sa * m->inverse_sine;
    b = sb * m->inverse_sine;
  }
  float3 r0, r1, r2;
  quaternion_rows(a * m->rotation[0] + b * m->rotation[1], &r0, &r1, &r2);
  const float3 d = s * m->stretch_diagonal[0].xyz + t * m->stretch_diagonal[1].xyz;
  const float3 o = s * m->stretch_off[0].xyz + t * m->stretch_off[1].xyz; /* S01, S02, S12 */
  /* S^-1 = adj(S) / det(S), symmetric. */
  const float c00 = d.y * d.z - o.z * o.z, c01 = o.y * o.z - o.x * d.z, c02 = o.x * o.z - d.y * o.y;
  const float c11 = d.x * d.z - o.y * o.y, c12 = o.x * o.y - d.x * o.z, c22 = d.x * d.y - o.x * o.x;
  const float det = d.x * c00 + o.x * c01 + o.y * c02;
  const float3 s0 = (float3)(c00, c01, c02) / det, s1 = (float3)(c01, c11, c12) / det,
               s2 = (float3)(c02, c12, c22) / det;
  /* Row i of M^-1 = S^-1 R^T holds row i of S^-1 against each row of R. */
  const float3 m0 = (float3)(dot3(s0, r0), dot3(s0, r1), dot3(s0, r2));
  const float3 m1 = (float3)(dot3(s1, r0), dot3(s1, r1), dot3(s1, r2));
  const float3 m2 = (float3)(dot3(s2, r0), dot3(s2, r1), dot3(s2, r2));
  InstanceFrame f;
  f.to_object[0] = (float4)(m0, -dot3(m0, translation));
  f.to_object[1] = (float4)(m1, -dot3(m1, translation));
  f.to_object[2] = (float4)(m2, -dot3(m2, translation));
  f.normal_to_world[0] = (float4)(m0.x, m1.x, m2.x, 0.0f);
  f.normal_to_world[1] = (float4)(m0.y, m1.y, m2.y, 0.0f);
  f.normal_to_world[2] = (float4)(m0.z, m1.z, m2.z, 0.0f);
  return f;
}

/* Rows 0..2 of M^-1 at `time` of something placed by `motion` (an instance's or a mesh leaf's
 * field) and, when it does not move, by `still` (its own rows): all that a ray test needs, read
 * without the normals' map. */
CLRT_INLINE void to_object_rows(u32 motion, __global const f4* still,
                                __global const InstanceMotion* motions, float time, float4* rows) {
  /* Row by row, not in a loop: PoCL left the looped copies in memory, and every still ray test
   * then read its rows back from the stack (3-7% of the search). */
  if (has_motion(motion)) {
    const InstanceFrame f = motion_frame(motions + motion, time);
    rows[0] = f.to_object[0];
    rows[1] = f.to_object[1];
    rows[2] = f.to_object[2];
  } else {
    rows[0] = still[0];
    rows[1] = still[1];
    rows[2] = still[2];
  }
}

/* The maps an instance that does not move holds itself; the normals' map is the transpose of
 * M^-1's upper 3x3, as for a moving one. */
CLRT_INLINE InstanceFrame still_frame(__global const Instance* inst) {
  InstanceFrame f; /* row by row, as in to_object_rows */
  f.to_object[0] = inst->world_to_object[0];
  f.to_object[1] = inst->world_to_object[1];
  f.to_object[2] = inst->world_to_object[2];
  f.normal_to_world[0] = (float4)(f.to_object[0].x, f.to_object[1].x, f.to_object[2].x, 0.0f);
  f.normal_to_world[1] = (float4)(f.to_object[0].y, f.to_object[1].y, f.to_object[2].y, 0.0f);
  f.normal_to_world[2] = (float4)(f.to_object[0].z, f.to_object[1].z, f.to_object[2].z, 0.0f);
  return f;
}

/* Instance `inst`'s maps at `time`. */
CLRT_INLINE InstanceFrame instance_frame(__global const Instance* inst,
                                         __global const InstanceMotion* motions, float time) {
  if (has_motion(inst->motion)) return motion_frame(motions + inst->motion, time);
  return still_frame(inst);
}

#endif
