// Owen-scrambled, shuffled 2D Sobol points (Burley 2020, "Practical Hash-based Owen
// Scrambling"), the low-discrepancy numbers of sampler.h.
#ifndef WP_SOBOL_H
#define WP_SOBOL_H

#include "rng.h"

WP_BEGIN

// The bits of x in reverse order (OpenCL 1.2 has no builtin for it).
WP_FN uint reverseBits(uint x) {
  x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
  x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
  x = ((x >> 4u) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4u);
  x = ((x >> 8u) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8u);
  return (x >> 16u) | (x << 16u);
}

// A seeded permutation of 32-bit words in which each bit is flipped or not depending only
// on the bits below it (Laine & Karras 2011; the constants are Burley's): applied to a
// bit-reversed fraction it is a nested uniform (Owen) scramble, which keeps a net a net.
WP_FN uint laineKarrasPermutation(uint x, uint seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// The second Sobol dimension, bit-reversed: its generator is the Pascal matrix mod 2, so
// digit j of the fraction (weight 2^-(j+1)) is the XOR of the index bits k whose binary
// digits include j's (Lucas' theorem). That sum over supersets takes five masked shifts,
// so no direction-number table is needed.
WP_FN uint sobolPascalReversed(uint index) {
  uint x = index;
  x ^= (x >> 1u) & 0x55555555u;
  x ^= (x >> 2u) & 0x33333333u;
  x ^= (x >> 4u) & 0x0f0f0f0fu;
  x ^= (x >> 8u) & 0x00ff00ffu;
  x ^= (x >> 16u) & 0x0000ffffu;
  return x;
}

// A 32-bit fixed-point fraction as a float in [0, 1) (24 bits, so it never rounds to 1).
WP_FN float fractionToFloat(uint x) { return toFloat(x >> 8u) * 5.9604644775390625e-8f; }

// Burley's shuffle of a pixel's sample indices: the index's bits, reversed, Owen-scrambled.
// The first 2^k indices map onto one aligned block of 2^k Sobol points, which is a
// (0, k, 2)-net, so every power-of-two prefix of a pixel's samples is stratified, and
// sample s depends on s alone (split-invariant).
WP_FN uint shuffledIndex(uint index, uint seed) { return reverseBits(laineKarrasPermutation(reverseBits(index), seed)); }

// The Owen-scrambled fraction whose digits, most significant first, are the bits of
// `reversedFraction` from the lowest up.
WP_FN float owenScrambled(uint reversedFraction, uint seed) {
  return fractionToFloat(reverseBits(laineKarrasPermutation(reversedFraction, seed)));
}

// Point `index` of the shuffled, Owen-scrambled 2D Sobol sequence chosen by `seed`: the
// van der Corput dimension (the index reversed) and the Pascal one.
WP_FN vec2 sobolScrambled2(uint index, uint seed) {
  uint shuffled = shuffledIndex(index, seed);
  return make_vec2(owenScrambled(shuffled, pcgHash(seed ^ 0x2c1b3c6du)),
                   owenScrambled(sobolPascalReversed(shuffled), pcgHash(seed ^ 0x297a2d39u)));
}

// Point `index` of the shuffled, Owen-scrambled van der Corput sequence chosen by `seed`.
WP_FN float sobolScrambled1(uint index, uint seed) {
  return owenScrambled(shuffledIndex(index, seed), pcgHash(seed ^ 0x2c1b3c6du));
}

WP_END

#endif
