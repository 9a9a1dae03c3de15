// The HDR sky: an equirectangular (lat-long) radiance map around the scene, rotated about +y,
// looked up by direction and importance-sampled by luminance for next event estimation.
#ifndef WP_ENVIRONMENT_H
#define WP_ENVIRONMENT_H

#include "lights.h"

WP_BEGIN

// The map's frame (y up, as glTF): v = theta / pi, theta measured from +y, so the top row
// (v = 0) is the zenith and the bottom row the nadir; u = 1/2 + phi / (2 pi) with phi =
// atan2(x, -z), so the middle of the map (u = 1/2) is the -z direction a default glTF camera
// looks along, u = 3/4 is +x (to that camera's right), u = 1/4 is -x and u = 0 or 1 is +z.
// Seen from inside, the picture is not mirrored. A sky rotated by `rotation` radians turns
// right-handed about +y (counterclockwise seen from above): what the map shows at direction
// m appears at Ry(rotation) m, so +x moves towards -z.
//
// Radiance is looked up nearest-neighbour: each texel is constant over its patch of (u, v).
// The sampling density is piecewise constant over the same patches, proportional to the
// texel's luminance times sin(theta) at its row's centre (the solid angle a texel spans),
// so sampling and lookup see the same texels and radiance / pdf varies within a texel only
// as sin(theta) does.
//
// The distribution is a 2D piecewise-constant one (Pharr, Jakob & Humphreys, PBRT 3rd ed.,
// §13.6.7): a marginal CDF over rows, height + 1 floats from 0 to 1, and for each row a
// conditional CDF over its columns, width + 1 floats from 0 to 1, rows one after another
// (row r starts at r * (width + 1)). Both are built on the host (src/scene/environment_map.h)
// and read through WP_LOAD(skyMarginal, i), WP_LOAD(skyConditional, i) and
// WP_LOAD(skyRadiance, i) (texel i = row * width + column, top row first; rgb radiance, w
// unused).

// The two-argument arctangent: OpenCL spells it atan2, GLSL and GLM atan(y, x).
#if defined(__OPENCL_VERSION__) || defined(__OPENCL_C_VERSION__)
#define wpAtan2(y, x) atan2((y), (x))
#else
#define wpAtan2(y, x) atan((y), (x))
#endif


WP_FN GpuEnvironment makeEnvironment(uint width, uint height, float intensity, float rotation) {
  GpuEnvironment env;
  env.intensity = intensity;
  env.rotation = rotation;
  env.selectionProbability = 0.0f;
  env.unused0 = 0.0f;
  env.width = width;
  env.height = height;
  env.unused1 = 0u;
  env.unused2 = 0u;
  return env;
}

// Map coordinates (u, v) in [0, 1]^2 of the world direction `direction` (unit).
WP_FN vec2 environmentUv(GpuEnvironment env, vec3 direction) {
  float u = 0.5f + (wpAtan2(direction.x, -direction.z) + env.rotation) * (0.5f * WP_INV_PI);
  u = u - floor(u);
  // theta from atan2 rather than acos(y): near the poles y = cos(theta) has lost theta's
  // digits, while the horizontal length still holds sin(theta) to full precision.
  float v = wpAtan2(sqrt(direction.x * direction.x + direction.z * direction.z), direction.y) * WP_INV_PI;
  return make_vec2(u, v);
}

// The unit world direction at map coordinates (u, v): the inverse of environmentUv. A sample
// warp, whose sines and cosines are WP_WARP_SIN and WP_WARP_COS (the native ones on OpenCL:
// PoCL's full-precision argument reduction had been 9% of a render of the HDR sky sample).
WP_FN vec3 environmentDirection(GpuEnvironment env, vec2 uv) {
  float phi = 2.0f * WP_PI * (uv.x - 0.5f) - env.rotation;
  float theta = WP_PI * uv.y;
  float sinTheta = WP_WARP_SIN(theta);
  return make_vec3(sinTheta * WP_WARP_SIN(phi), WP_WARP_COS(theta), -sinTheta * WP_WARP_COS(phi));
}

// sin(theta) at map coordinate v, the lat-long map's Jacobian in the densities below: the
// warp's own sine, so that a sample's density and the density of its direction agree.
WP_FN float environmentSinTheta(float v) { return WP_WARP_SIN(WP_PI * v); }

// Index (row * width + column) of the texel holding (u, v).
WP_FN uint environmentTexel(GpuEnvironment env, vec2 uv) {
  uint column = min(toUint(uv.x * toFloat(env.width)), env.width - 1u);
  uint row = min(toUint(uv.y * toFloat(env.height)), env.height - 1u);
  return row * env.width + column;
}

// Sky radiance seen along `direction` (unit), intensity included: the nearest texel.
WP_FN vec3 environmentRadiance(WP_BUFFERS GpuEnvironment env, vec3 direction) {
  // A uniform sky (the default white one, --sky-color, or none: one texel) needs no map
  // coordinates, which cost two arctangents (slow in PoCL's math library); Vulkan compiles
  // them out of a scene whose sky has one texel (WP_SCENE_SKY_MAP), since lavapipe runs the
  // branch whatever its condition.
  uint index = 0u;
  if (WP_SCENE_SKY_MAP && env.width * env.height > 1u) {
    index = environmentTexel(env, environmentUv(env, direction));
  }
  vec4 texel = WP_LOAD(skyRadiance, index);
  return make_vec3(texel.x, texel.y, texel.z) * env.intensity;
}

// Density over (u, v) of choosing texel `texel`: its row's marginal probability times its
// column's conditional one, over the area of a texel in (u, v).
WP_FN float environmentUvPdf(WP_BUFFERS GpuEnvironment env, uint texel) {
  uint row = texel / env.width;
  uint column = texel - row * env.width;
  uint base = row * (env.width + 1u);
  float rowProbability = WP_LOAD(skyMarginal, row + 1u) - WP_LOAD(skyMarginal, row);
  float columnProbability = WP_LOAD(skyConditional, base + column + 1u) - WP_LOAD(skyConditional, base + column);
  return rowProbability * columnProbability * toFloat(env.width) * toFloat(env.height);
}

// Solid-angle density of sampleEnvironment choosing `direction` (unit): the (u, v) density
// divided by the Jacobian of the lat-long map, d(omega) = 2 pi^2 sin(theta) du dv. Zero at
// the poles, where the map degenerates and no sample lands.
WP_FN float environmentPdf(WP_BUFFERS GpuEnvironment env, vec3 direction) {
  vec2 uv = environmentUv(env, direction);
  float sinTheta = environmentSinTheta(uv.y);
  if (sinTheta <= 0.0f) return 0.0f;
  return environmentUvPdf(WP_BUFFERS_ARG env, environmentTexel(env, uv)) / (2.0f * WP_PI * WP_PI * sinTheta);
}

// The texel (row * width + column) sampled by u in [0, 1)^2: u.y finds the row whose
// marginal interval [cdf[row], cdf[row + 1]) holds it, then u.x the column within that row's
// conditional CDF, each by a binary search that keeps cdf[lo] <= u < cdf[hi]. Intervals of
// zero probability are empty and never chosen.
WP_FN uint findEnvironmentTexel(WP_BUFFERS uint width, uint height, vec2 u) {
  uint lo = 0u;
  uint hi = height;
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (WP_LOAD(skyMarginal, mid) <= u.y) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  uint row = lo;
  uint base = row * (width + 1u);
  lo = 0u;
  hi = width;
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (WP_LOAD(skyConditional, base + mid) <= u.x) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return row * width + lo;
}

// A direction towards the sky with density proportional to its texels' luminance times
// sin(theta), for next event estimation: u.y picks the row, u.x the column, and what is left
// of each places the point uniformly within the texel's (u, v) patch. The pdf is in solid
// angle and excludes the choice between the sky and other lights; distance is WP_FLT_MAX
// (the shadow ray runs to infinity); radiance includes the intensity.
WP_FN LightSample sampleEnvironment(WP_BUFFERS GpuEnvironment env, vec2 u) {
  uint width = env.width;
  uint height = env.height;
  uint texel = findEnvironmentTexel(WP_BUFFERS_ARG width, height, u);
  uint row = texel / width;
  uint column = texel - row * width;
  uint base = row * (width + 1u);
  float m0 = WP_LOAD(skyMarginal, row);
  float m1 = WP_LOAD(skyMarginal, row + 1u);
  float c0 = WP_LOAD(skyConditional, base + column);
  float c1 = WP_LOAD(skyConditional, base + column + 1u);
  // The remainders are below 1 in exact arithmetic; rounding could make them 1, the edge of
  // the next texel.
  float dv = min((u.y - m0) / (m1 - m0), 0.99999994f);
  float du = min((u.x - c0) / (c1 - c0), 0.99999994f);
  vec2 uv = make_vec2((toFloat(column) + du) / toFloat(width), (toFloat(row) + dv) / toFloat(height));
  float sinTheta = environmentSinTheta(uv.y);
  LightSample s = noLightSample();
  s.direction = environmentDirection(env, uv);
  s.distance = WP_FLT_MAX;
  vec4 radiance = WP_LOAD(skyRadiance, texel);
  s.radiance = make_vec3(radiance.x, radiance.y, radiance.z) * env.intensity;
  float uvPdf = environmentUvPdf(WP_BUFFERS_ARG env, texel);
  s.pdf = sinTheta > 0.0f ? uvPdf / (2.0f * WP_PI * WP_PI * sinTheta) : 0.0f;
  return s;
}

WP_END

#endif
