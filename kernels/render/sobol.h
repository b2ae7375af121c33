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
 * below it (an addition and multiplications by even numbers carry only upwards): applied to
 * reversed bits, Owen's nested uniform scramble, which flips each binary digit of a fraction
 * depending on the digits before it (Laine and Karras's hash, with Burley's constants). */
CLRT_INLINE uint laine_karras(uint x, uint seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

/* The second Sobol dimension's digits of `index`, digit i (worth 2^-(i+1)) in bit i: the
 * Pascal matrix mod 2, under which digit i is the sum of the index's bits j whose positions
 * contain i's bits (Lucas' theorem), summed over one bit of the position at a time. No loop,
 * no branch: PoCL keeps a kernel with a loop out of its SIMD lanes. */
CLRT_INLINE uint sobol_dim1_digits(uint index) {
  index ^= (index >> 1) & 0x55555555u;
  index ^= (index >> 2) & 0x33333333u;
  index ^= (index >> 4) & 0x0f0f0f0fu;
  index ^= (index >> 8) & 0x00ff00ffu;
  return index ^ ((index >> 16) & 0x0000ffffu);
}

/* Sample k of the pair of random numbers `key` names, in [0, 1)^2: point k' of the Sobol
 * sequence's first two dimensions (the van der Corput sequence, whose digits are the index's
 * bits, and the Pascal matrix's), Owen-scrambled with seeds of its own. k' is k scrambled the
 * same way (a shuffle that keeps the first 2^m samples an aligned block of the sequence, so a
 * net), so that pairs of different keys are not correlated with each other. Digits are kept in
 * reversed order until the end, where each coordinate is reversed once into a fraction. */
CLRT_INLINE float2 sobol_sample(uint key, uint k) {
  const uint s0 = hash_u32(key), s1 = hash_u32(s0), s2 = hash_u32(s1);
  const uint index = reverse_bits(laine_karras(reverse_bits(k), s0));
  return (float2)(uniform_float(reverse_bits(laine_karras(index, s1))),
                  uniform_float(reverse_bits(laine_karras(sobol_dim1_digits(index), s2))));
}

/* The key of a pair used at path depth `depth` for `use` (a stream index of random.h or of
 * render/path_step.h, or a light sample's index) in the pixel whose stream is `pixel`. */
CLRT_INLINE uint sample_key(uint pixel, uint depth, uint use) {
  return hash_combine(hash_combine(pixel, depth), use);
}

#endif
