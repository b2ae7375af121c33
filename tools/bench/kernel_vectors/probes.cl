/* Probe kernels for kernel_vectors.py --probes: each is one feature of clrt's kernels in a
 * kernel of a few lines, so that whether PoCL runs its work-items in SIMD lanes can be read off
 * that feature alone. All take the same arguments (probe_kernels.cpp binds them once):
 *   in4    float4 records, in    floats (4 per work-item), out    floats (4 per work-item),
 *   count  work-items with data (the launch may have more). */
#pragma OPENCL FP_CONTRACT OFF

#define PROBE(name) \
  __kernel void name(__global const float4* in4, __global const float* in, __global float* out, uint count)

/* Scalar loads, arithmetic and stores: the baseline. */
PROBE(scalar_arithmetic) {
  const uint i = get_global_id(0);
  out[i] = in[i] * in[i] + 1.0f;
}

/* The same with what every clrt kernel has: an early return past the queue's end, and a
 * correctly rounded square root and division, and a select. */
PROBE(scalar_return_sqrt_divide) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float x = in[4 * i], y = in[4 * i + 1], z = in[4 * i + 2];
  const float len = sqrt(x * x + y * y + z * z);
  out[i] = x > 0.0f ? y / len : z / len;
}

/* A record read as a float4 (as rays, hits and colours are), then scalar arithmetic. */
PROBE(float4_record) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float4 v = in4[i];
  out[i] = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

/* Scalar loads, but the arithmetic in float3 (as kernels/math/exact.h writes it). */
PROBE(float3_arithmetic) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float3 v = (float3)(in[4 * i], in[4 * i + 1], in[4 * i + 2]) * 2.0f + (float3)(1.0f);
  out[i] = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

/* A loop of a fixed count. */
PROBE(fixed_loop) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  float sum = 0.0f;
  for (int k = 0; k < 4; ++k) sum += in[4 * i + k] * in[4 * i + k];
  out[i] = sum;
}

/* A loop whose count depends on the data (the lights of a scene, a node stack). */
PROBE(data_loop) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  float sum = 0.0f;
  const uint n = (uint)in[4 * i + 3] & 7u;
  for (uint k = 0; k < n; ++k) sum += in[4 * i + (k & 3u)];
  out[i] = sum;
}

/* A switch (the light kinds, the transport modes). */
PROBE(switch_statement) {
  const uint i = get_global_id(0);
  if (i >= count) return;
  const float x = in[4 * i];
  float r;
  switch ((uint)in[4 * i + 3] & 3u) {
    case 0: r = x; break;
    case 1: r = x * x; break;
    case 2: r = sqrt(x); break;
    default: r = 1.0f / x; break;
  }
  out[i] = r;
}
