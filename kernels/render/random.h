/* Counter-based random numbers: every value is a hash of where it is used (seed, pixel,
 * sample, place in the ray tree, light sample), never of a thread or of scheduling, so a
 * render gives the same bits for any thread count, wavefront size or device. */
#ifndef CLRT_RENDER_RANDOM_H
#define CLRT_RENDER_RANDOM_H

/* A PCG-style integer permutation with good avalanche. */
CLRT_INLINE uint hash_u32(uint x) {
  uint state = x * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

CLRT_INLINE uint hash_combine(uint a, uint b) {
  return hash_u32(a ^ (hash_u32(b) + 0x9e3779b9u + (a << 6) + (a >> 2)));
}

/* Uniform in [0, 1) from the top 24 bits: exactly representable floats. */
CLRT_INLINE float uniform_float(uint h) { return (float)(h >> 8) * (1.0f / 16777216.0f); }

/* The random stream of a pixel: (seed, pixel). */
CLRT_INLINE uint pixel_stream(uint seed, uint pixel) { return hash_combine(hash_u32(seed), pixel); }

/* The random stream of a camera ray: (seed, pixel, sample). */
CLRT_INLINE uint camera_path(uint seed, uint pixel, uint sample) {
  return hash_combine(pixel_stream(seed, pixel), sample);
}

#define CLRT_BRANCH_REFLECT 1u
#define CLRT_BRANCH_REFRACT 2u

/* A secondary ray's stream: its parent's and the branch taken. */
CLRT_INLINE uint child_path(uint parent, uint branch) { return hash_combine(parent, branch); }

/* The stream indices of the camera's jitter, of its lens sample and of its time; light samples use indices
 * from 0 up and path mode's own uses the two below CLRT_CAMERA_JITTER (render/path_step.h), so
 * none share numbers. */
#define CLRT_CAMERA_JITTER 0xffffffffu
#define CLRT_LENS_JITTER 0xfffffffcu
#define CLRT_TIME_JITTER 0xfffffffbu

/* Two jitters for stratum `index` of a stream, e.g. one camera sample or one light sample. */
CLRT_INLINE float2 jitter2(uint path, uint index) {
  uint h = hash_combine(path, index);
  return (float2)(uniform_float(h), uniform_float(hash_u32(h)));
}

/* Element i of a shuffle of 0 .. n-1 chosen by `key` (i < n): a bijection of the next power of
 * two's bits (odd multiplications, additions and shifts that fold the high bits down), applied
 * again until it lands below n, which walks the cycle of i within 0 .. n-1. */
CLRT_INLINE uint shuffled_index(uint i, uint n, uint key) {
  uint mask = n - 1u;
  mask |= mask >> 1;
  mask |= mask >> 2;
  mask |= mask >> 4;
  mask |= mask >> 8;
  mask |= mask >> 16;
  const uint a = hash_u32(key), b = hash_u32(a);
  do {
    i = (i * (a | 1u) + b) & mask;
    i ^= i >> 3;
    i = (i * ((b << 1) | 1u) + a) & mask;
    i ^= i >> 1;
  } while (i >= n);
  return i;
}

/* Position in [0,1)^2 of sample `k` of a grid_u x grid_v stratification: one jitter per cell. */
CLRT_INLINE float2 stratified(uint k, uint grid_u, uint grid_v, float2 jitter) {
  return (float2)(((float)(k % grid_u) + jitter.x) / (float)grid_u,
                  ((float)(k / grid_u) + jitter.y) / (float)grid_v);
}

#endif
