// Owen-scrambled, shuffled 2D Sobol points (Burley 2020, "Practical Hash-based Owen
// Scrambling"), the low-discrepancy numbers of sampler.h.
//
// Each number takes three bit reversals, two Laine-Karras permutations and three hashes,
// all on 32-bit integers: on a CPU device, where a work-item is a thread's scalar code, the
// Sobol sampler's shade took 1.3 s where the independent one's took 1.0 s (PoCL, the shared
// Cornell box, 512x512, 16 spp). So the numbers are made four at a time, one per lane of a
// uvec4 (sobolScrambled4: a vertex's seven numbers in two calls, sampler.h), which a CPU runs
// in its vector registers; where work-items are SIMD lanes (GPUs, lavapipe) the lanes cost
// what four calls would. What remains is a chain of a dozen dependent multiplies, which
// shade starts before anything else (integrator.h). The 1D and 2D draws are lanes of the
// same function, and the images are bit for bit those of the scalar code.
#ifndef WP_SOBOL_H
#define WP_SOBOL_H

#include "rng.h"

WP_BEGIN

// The helpers below that both forms use are defined for a uint and, with the suffix 4, for
// every lane of a uvec4, by the same statements (OpenCL C has no overloading).

// The bits of x in reverse order (OpenCL 1.2 has no builtin for it).
#define WP_DEFINE_REVERSE_BITS(name, T)                                 \
  WP_FN T name(T x) {                                                   \
    x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);          \
    x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);          \
    x = ((x >> 4u) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4u);          \
    x = ((x >> 8u) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8u);          \
    return (x >> 16u) | (x << 16u);                                     \
  }
WP_DEFINE_REVERSE_BITS(reverseBits, uint)
WP_DEFINE_REVERSE_BITS(reverseBits4, uvec4)

// A seeded permutation of 32-bit words in which each bit is flipped or not depending only
// on the bits below it (Laine & Karras 2011; the constants are Burley's): applied to a
// bit-reversed fraction it is a nested uniform (Owen) scramble, which keeps a net a net.
// Only the four-lane form is needed.
WP_FN uvec4 laineKarrasPermutation4(uvec4 x, uvec4 seed) {
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
#define WP_DEFINE_SOBOL_PASCAL_REVERSED(name, T) \
  WP_FN T name(T index) {                        \
    T x = index;                                 \
    x ^= (x >> 1u) & 0x55555555u;                \
    x ^= (x >> 2u) & 0x33333333u;                \
    x ^= (x >> 4u) & 0x0f0f0f0fu;                \
    x ^= (x >> 8u) & 0x00ff00ffu;                \
    x ^= (x >> 16u) & 0x0000ffffu;               \
    return x;                                    \
  }
WP_DEFINE_SOBOL_PASCAL_REVERSED(sobolPascalReversed, uint)
WP_DEFINE_SOBOL_PASCAL_REVERSED(sobolPascalReversed4, uvec4)

// The seeds that scramble the two coordinates of a 2D sequence, from the sequence's seed.
#define WP_SOBOL_SCRAMBLE_FIRST 0x2c1b3c6du
#define WP_SOBOL_SCRAMBLE_SECOND 0x297a2d39u

// Four numbers at once, lane by lane: of point `index` of the shuffled, Owen-scrambled 2D
// Sobol sequence chosen by seed[k], lane k is the first coordinate (the van der Corput
// dimension, the index reversed) where second[k] is 0, the second (the Pascal one) where it
// is all ones. Burley's shuffle of a pixel's sample indices (the index's bits, reversed,
// Owen-scrambled) maps the first 2^k indices onto one aligned block of 2^k Sobol points, a
// (0, k, 2)-net, so every power-of-two prefix of a pixel's samples is stratified, and sample
// s depends on s alone (split-invariant). Each coordinate is then Owen-scrambled by a seed of
// its own. A fixed-point fraction becomes a float in [0, 1) of 24 bits, so it never rounds
// to 1.
WP_FN_INLINED vec4 sobolScrambled4(uint index, uvec4 seed, uvec4 second) {
  uint reversedIndex = reverseBits(index);
  uvec4 shuffled =
      reverseBits4(laineKarrasPermutation4(make_uvec4(reversedIndex, reversedIndex, reversedIndex, reversedIndex), seed));
  uvec4 fraction = shuffled ^ ((sobolPascalReversed4(shuffled) ^ shuffled) & second);
  uvec4 scramble =
      pcgHash4(seed ^ (WP_SOBOL_SCRAMBLE_FIRST ^ ((WP_SOBOL_SCRAMBLE_FIRST ^ WP_SOBOL_SCRAMBLE_SECOND) & second)));
  return toFloat4(reverseBits4(laineKarrasPermutation4(fraction, scramble)) >> 8u) * 5.9604644775390625e-8f;
}

// The lanes' choice of coordinate in sobolScrambled4.
#define WP_SOBOL_FIRST 0u
#define WP_SOBOL_SECOND 0xffffffffu

// Point `index` of the shuffled, Owen-scrambled 2D Sobol sequence chosen by `seed`.
WP_FN vec2 sobolScrambled2(uint index, uint seed) {
  vec4 u = sobolScrambled4(index, make_uvec4(seed, seed, seed, seed),
                           make_uvec4(WP_SOBOL_FIRST, WP_SOBOL_SECOND, WP_SOBOL_FIRST, WP_SOBOL_SECOND));
  return make_vec2(u.x, u.y);
}

// Point `index` of the shuffled, Owen-scrambled van der Corput sequence chosen by `seed`.
WP_FN float sobolScrambled1(uint index, uint seed) { return sobolScrambled2(index, seed).x; }

WP_END

#endif
