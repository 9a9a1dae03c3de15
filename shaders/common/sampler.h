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

// The seed of dimension `dimension` of the paths of pixel seed `pathSeed`; with the suffix 4,
// of four dimensions at once (sobol.h).
#define WP_DEFINE_SOBOL_DIMENSION_SEED(name, T, hash) \
  WP_FN T name(uint pathSeed, T dimension) { return hash(pathSeed ^ hash(dimension + 0x3c6ef372u)); }
WP_DEFINE_SOBOL_DIMENSION_SEED(sobolDimensionSeed, uint, pcgHash)
WP_DEFINE_SOBOL_DIMENSION_SEED(sobolDimensionSeed4, uvec4, pcgHash4)

// The first dimension of the vertex the ray of `bounce` reaches.
WP_FN uint vertexDimension(uint bounce) { return WP_DIMS_CAMERA + bounce * WP_DIMS_PER_BOUNCE; }

// Whether the draws are the Sobol sampler's. Vulkan compiles the independent sampler only
// into the stages of a render that uses it (WP_RENDER_INDEPENDENT_SAMPLER, prelude_glsl.h):
// lavapipe runs both sides of every branch, so each draw of a Sobol render also ran the PCG
// stream's.
WP_FN bool drawsSobol(uint samplerKind) { return !WP_RENDER_INDEPENDENT_SAMPLER || samplerKind == WP_SAMPLER_SOBOL; }

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
  p.state = drawsSobol(samplerKind) ? pcgHash(pixel ^ pcgHash(seed ^ 0x5851f42du)) : rngSeed(pixel, sampleIndex, seed);
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
  if (drawsSobol(samplerKind)) {
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
  if (drawsSobol(samplerKind)) {
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
  if (drawsSobol(samplerKind)) {
    return sobolScrambled1(p.sampleIndex, sobolDimensionSeed(p.state, WP_DIM_TIME));
  }
  return rngTime(p.state);
}

// The numbers of a camera ray: its pixel's film point, its aperture point and its shutter
// time, as pathTime, drawPath2 (film) and drawPath2 (lens) give them, and the path's
// samples after them. Sobol draws both points in one sobolScrambled4.
WP_STRUCT(CameraDraws)
  PathSamples samples;
  vec2 film;
  vec2 lens;
  float time;
WP_STRUCT_END(CameraDraws)

WP_FN_INLINED CameraDraws drawCamera(uint samplerKind, PathSamples p) {
  CameraDraws d;
  d.time = pathTime(samplerKind, p);
  if (drawsSobol(samplerKind)) {
    vec4 u = sobolScrambled4(p.sampleIndex,
                             sobolDimensionSeed4(p.state, make_uvec4(WP_DIM_FILM, WP_DIM_FILM, WP_DIM_LENS, WP_DIM_LENS)),
                             make_uvec4(WP_SOBOL_FIRST, WP_SOBOL_SECOND, WP_SOBOL_FIRST, WP_SOBOL_SECOND));
    d.samples = p;
    d.film = make_vec2(u.x, u.y);
    d.lens = make_vec2(u.z, u.w);
    return d;
  }
  PathDraw2 film = drawPath2(samplerKind, p, WP_DIM_FILM);
  PathDraw2 lens = drawPath2(samplerKind, film.samples, WP_DIM_LENS);
  d.samples = lens.samples;
  d.film = film.u;
  d.lens = lens.u;
  return d;
}

// The numbers of the path vertex of `bounce`, as drawPath3 (the light sample's choice and
// point), drawPath3 (the BSDF sample's lobe and direction) and drawPath1 (Russian roulette)
// give them in that order, and the path's samples after them. The light's are drawn only
// with `light` and the roulette's only with `roulette` (0 otherwise), so that the
// independent stream moves on only by what the vertex uses. Sobol draws all seven in two
// sobolScrambled4.
WP_STRUCT(VertexDraws)
  PathSamples samples;
  vec3 light;  // x chooses, y and z place
  vec3 bsdf;   // likewise
  float roulette;
WP_STRUCT_END(VertexDraws)

WP_FN_INLINED VertexDraws drawVertex(uint samplerKind, PathSamples p, uint bounce, bool light, bool roulette) {
  VertexDraws d;
  uint first = vertexDimension(bounce);
  if (drawsSobol(samplerKind)) {
    // The first coordinates of the four dimensions, then the second ones of the two 2D
    // dimensions and the roulette number (twice, filling the lanes).
    vec4 firsts = sobolScrambled4(
        p.sampleIndex,
        sobolDimensionSeed4(p.state, first + make_uvec4(WP_DIM_LIGHT_CHOICE, WP_DIM_LIGHT_POINT, WP_DIM_BSDF_LOBE,
                                                        WP_DIM_BSDF_DIRECTION)),
        make_uvec4(WP_SOBOL_FIRST, WP_SOBOL_FIRST, WP_SOBOL_FIRST, WP_SOBOL_FIRST));
    vec4 rest = sobolScrambled4(
        p.sampleIndex,
        sobolDimensionSeed4(p.state, first + make_uvec4(WP_DIM_LIGHT_POINT, WP_DIM_BSDF_DIRECTION, WP_DIM_ROULETTE,
                                                        WP_DIM_ROULETTE)),
        make_uvec4(WP_SOBOL_SECOND, WP_SOBOL_SECOND, WP_SOBOL_FIRST, WP_SOBOL_FIRST));
    d.samples = p;
    d.light = make_vec3(firsts.x, firsts.y, rest.x);
    d.bsdf = make_vec3(firsts.z, firsts.w, rest.y);
    d.roulette = rest.z;
    return d;
  }
  d.light = make_vec3(0.0f, 0.0f, 0.0f);
  d.roulette = 0.0f;
  if (light) {
    PathDraw3 lightDraw = drawPath3(samplerKind, p, first + WP_DIM_LIGHT_CHOICE);
    p = lightDraw.samples;
    d.light = lightDraw.u;
  }
  PathDraw3 bsdfDraw = drawPath3(samplerKind, p, first + WP_DIM_BSDF_LOBE);
  p = bsdfDraw.samples;
  d.bsdf = bsdfDraw.u;
  if (roulette) {
    PathDraw1 rouletteDraw = drawPath1(samplerKind, p, first + WP_DIM_ROULETTE);
    p = rouletteDraw.samples;
    d.roulette = rouletteDraw.u;
  }
  d.samples = p;
  return d;
}

WP_END

#endif
