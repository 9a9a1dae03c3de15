// Random numbers: a 32-bit PCG stream per path, seeded by hashing (pixel, sample, seed); the
// independent sampler of sampler.h, and the hash that seeds the Sobol one.
#ifndef WP_RNG_H
#define WP_RNG_H

#include "portable.h"

WP_BEGIN

// PCG-RXS-M-XS hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering"): a
// well-mixed bijection on 32 bits, used to seed streams so neighbouring pixels decorrelate.
// Defined for a uint and, as pcgHash4, for each lane of a uvec4 by the same statements, so
// that the two agree bit for bit (sobol.h draws four Sobol numbers at once).
#define WP_DEFINE_PCG_HASH(name, T)                                      \
  WP_FN T name(T v) {                                                    \
    T state = v * 747796405u + 2891336453u;                              \
    T word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;    \
    return (word >> 22u) ^ word;                                         \
  }
WP_DEFINE_PCG_HASH(pcgHash, uint)
WP_DEFINE_PCG_HASH(pcgHash4, uvec4)

// The stream state of path `pixel`, sample `sampleIndex`, for a render seeded by `seed`.
WP_FN uint rngSeed(uint pixel, uint sampleIndex, uint seed) {
  return pcgHash(pixel ^ pcgHash(sampleIndex ^ pcgHash(seed)));
}

// Advances the stream (the LCG step of PCG). Functions cannot write through references in
// every language, so callers write `state = rngNext(state); u = rngFloat(state);`.
WP_FN uint rngNext(uint state) { return state * 747796405u + 2891336453u; }

// A uniform float in [0, 1) from the current state (PCG's output permutation, 24 bits).
WP_FN float rngFloat(uint state) {
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  word = (word >> 22u) ^ word;
  return toFloat(word >> 8u) * 5.9604644775390625e-8f;
}

// A path's normalized shutter time in [0, 1) (motion blur), from the state rngSeed gave it,
// hashed apart from the stream (sampler.h says why).
WP_FN float rngTime(uint seedState) { return rngFloat(pcgHash(seedState ^ 0x6d2b79f5u)); }

WP_END

#endif
