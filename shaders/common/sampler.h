// The random numbers a path consumes, from one of two samplers (RenderParams.samplerKind): Owen-
// scrambled Sobol (sobol.h), stratified across a pixel's samples, or an independent PCG
// stream per path (rng.h). See docs/sampling.md.
#ifndef WP_SAMPLER_H
#define WP_SAMPLER_H

#include "sobol.h"

WP_BEGIN

#define WP_SAMPLER_SOBOL 0u
#define WP_SAMPLER_INDEPENDENT 1u

// The Sobol sampler's dimensions: each decision of a path has its own, so that it is
// stratified across the pixel's samples whatever the other decisions drew. A dimension is
// one 1D or 2D sequence, shuffled and scrambled by a seed of its own (padding, as in
// Burley 2020 and pbrt-v4), so there are as many as a path needs.
#define WP_DIM_TIME 0u  // 1D: shutter time
#define WP_DIM_FILM 1u  // 2D: the point in the pixel
#define WP_DIM_LENS 2u  // 2D: the point on the aperture
#define WP_DIMS_CAMERA 3u
// Per vertex, from WP_DIMS_CAMERA + bounce * WP_DIMS_PER_BOUNCE:
#define WP_DIM_LIGHT_CHOICE 0u     // 1D: the sky or which light
#define WP_DIM_LIGHT_POINT 1u      // 2D: the point on it
#define WP_DIM_BSDF_LOBE 2u        // 1D: the lobe
#define WP_DIM_BSDF_DIRECTION 3u   // 2D: the direction in it
#define WP_DIM_ROULETTE 4u         // 1D: Russian roulette
#define WP_DIMS_PER_BOUNCE 5u

// The seed of dimension `dimension` of the paths of pixel seed `pathSeed`.
WP_FN uint sobolDimensionSeed(uint pathSeed, uint dimension) {
  return pcgHash(pathSeed ^ pcgHash(dimension + 0x3c6ef372u));
}

// The first dimension of the vertex the ray of `bounce` reaches.
WP_FN uint vertexDimension(uint bounce) { return WP_DIMS_CAMERA + bounce * WP_DIMS_PER_BOUNCE; }

// What a path carries between draws: the PCG stream (independent) or the pixel's seed
// (Sobol), and its sample index in the pixel.
WP_STRUCT(PathSamples)
  uint state;
  uint sampleIndex;
WP_STRUCT_END(PathSamples)

// The samples of path `sampleIndex` of image pixel `pixel`, for a render seeded by `seed`.
WP_FN PathSamples startPathSamples(uint samplerKind, uint pixel, uint sampleIndex, uint seed) {
  PathSamples p;
  p.sampleIndex = sampleIndex;
  p.state = samplerKind == WP_SAMPLER_SOBOL ? pcgHash(pixel ^ pcgHash(seed ^ 0x5851f42du)) : rngSeed(pixel, sampleIndex, seed);
  return p;
}

// One number of dimension `dimension` (1D) and the samples after it.
WP_STRUCT(PathDraw1)
  PathSamples samples;
  float u;
WP_STRUCT_END(PathDraw1)

WP_FN_INLINED PathDraw1 drawPath1(uint samplerKind, PathSamples p, uint dimension) {
  PathDraw1 d;
  d.samples = p;
  if (samplerKind == WP_SAMPLER_SOBOL) {
    d.u = sobolScrambled1(p.sampleIndex, sobolDimensionSeed(p.state, dimension));
  } else {
    d.samples.state = rngNext(p.state);
    d.u = rngFloat(d.samples.state);
  }
  return d;
}

// A point of dimension `dimension` (2D) and the samples after it.
WP_STRUCT(PathDraw2)
  PathSamples samples;
  vec2 u;
WP_STRUCT_END(PathDraw2)

WP_FN_INLINED PathDraw2 drawPath2(uint samplerKind, PathSamples p, uint dimension) {
  PathDraw2 d;
  d.samples = p;
  if (samplerKind == WP_SAMPLER_SOBOL) {
    d.u = sobolScrambled2(p.sampleIndex, sobolDimensionSeed(p.state, dimension));
  } else {
    d.samples.state = rngNext(p.state);
    float u0 = rngFloat(d.samples.state);
    d.samples.state = rngNext(d.samples.state);
    d.u = make_vec2(u0, rngFloat(d.samples.state));
  }
  return d;
}

// A choice (1D, dimension `dimension`) and a point (2D, the next dimension), as light and
// BSDF sampling take them: u.x chooses, u.y and u.z place.
WP_STRUCT(PathDraw3)
  PathSamples samples;
  vec3 u;
WP_STRUCT_END(PathDraw3)

WP_FN_INLINED PathDraw3 drawPath3(uint samplerKind, PathSamples p, uint dimension) {
  PathDraw1 choice = drawPath1(samplerKind, p, dimension);
  PathDraw2 point = drawPath2(samplerKind, choice.samples, dimension + 1u);
  PathDraw3 d;
  d.samples = point.samples;
  d.u = make_vec3(choice.u, point.u.x, point.u.y);
  return d;
}

// The path's normalized shutter time in [0, 1). The independent sampler hashes it apart
// from the stream rather than drawing it, so that no other draw shifts and scenes without
// motion render bit for bit as they did before time existed.
WP_FN_INLINED float pathTime(uint samplerKind, PathSamples p) {
  if (samplerKind == WP_SAMPLER_SOBOL) {
    return sobolScrambled1(p.sampleIndex, sobolDimensionSeed(p.state, WP_DIM_TIME));
  }
  return rngTime(p.state);
}

WP_END

#endif
