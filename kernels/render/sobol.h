/* Path mode's samples: the first two dimensions of the Sobol sequence, Owen-scrambled with
 * hashes (Burley, "Practical Hash-based Owen Scrambling", JCGT 2020), one independent scramble
 * per pixel and per use of a pair of random numbers ("padding"). The samples of a pixel are
 * then stratified in every pair they use: the first 2^m of them form a (0, m, 2)-net, for the
 * camera jitter, each light sample and each bounce alike, where independent random numbers
 * clump. Keys are hashes of where a pair is used, never of a thread, so every integrator,
 * region and device draws the same numbers. */
#ifndef CLRT_RENDER_SOBOL_H
#define CLRT_RENDER_SOBOL_H

#include "random.h"

CLRT_INLINE uint reverse_bits(uint x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

/* A random permutation of 32-bit words in which each bit is flipped depending only on the bits
 * below it (an addition and multiplications by even numbers carry only upwards): on reversed
 * bits, Owen's nested uniform scramble, in which each binary digit of a coordinate is flipped
 * depending on the digits before it (Laine and Karras's hash, with Burley's constants). */
CLRT_INLINE uint owen_scramble(uint x, uint seed) {
  x = reverse_bits(x);
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return reverse_bits(x);
}

/* Point `index` of the Sobol sequence's first two dimensions, as 32-bit fractions: the
 * van der Corput sequence and the one of the Pascal matrix mod 2. The loop has a fixed count,
 * so the lanes of a SIMD device never wait on each other. */
CLRT_INLINE uint2 sobol_2d(uint index) {
  uint y = 0u, v = 0x80000000u, bits = index;
  for (uint i = 0; i < 32u; ++i) {
    y ^= v & (0u - (bits & 1u));
    bits >>= 1;
    v ^= v >> 1;
  }
  return (uint2)(reverse_bits(index), y);
}

/* Sample k of the pair of random numbers `key` names, in [0, 1)^2. The index is scrambled too
 * (a shuffle that keeps the first 2^m samples an aligned block of the sequence, so a net), so
 * that pairs of different keys are not correlated with each other. */
CLRT_INLINE float2 sobol_sample(uint key, uint k) {
  const uint2 p = sobol_2d(owen_scramble(k, hash_u32(key)));
  return (float2)(uniform_float(owen_scramble(p.x, hash_combine(key, 1u))),
                  uniform_float(owen_scramble(p.y, hash_combine(key, 2u))));
}

/* The key of a pair used at path depth `depth` for `use` (a stream index of random.h or of
 * render/path_step.h, or a light sample's index) in the pixel whose stream is `pixel`. */
CLRT_INLINE uint sample_key(uint pixel, uint depth, uint use) {
  return hash_combine(hash_combine(pixel, depth), use);
}

#endif
