// Next event estimation on emissive triangles: power-proportional selection through an
// alias table, a point uniform on the chosen triangle, densities in solid angle.
#ifndef WP_LIGHTS_H
#define WP_LIGHTS_H

#include "binding_table.h"
#include "sampling.h"
#include "surface.h"
#include "texture.h"

WP_BEGIN

WP_STRUCT(LightSample)
  vec3 direction;  // unit, from the shading point towards the sampled point
  float distance;  // to the sampled point
  vec3 radiance;   // emitted towards the shading point (0 behind a one-sided light)
  float pdf;       // solid-angle density, selection probability included; 0: no sample
WP_STRUCT_END(LightSample)

// Radiance leaving an emitter with geometric normal `lightNormal` (any length) towards
// `towardsViewer`: one-sided emitters emit on the side their normal points to.
WP_FN vec3 emittedRadiance(vec3 emission, bool doubleSided, vec3 lightNormal, vec3 towardsViewer) {
  return (doubleSided || dot(lightNormal, towardsViewer) > 0.0f) ? emission : make_vec3(0.0f, 0.0f, 0.0f);
}

// Index of the light chosen by u in [0, 1) from the alias table (GpuLight in layout.h).
WP_FN uint selectLight(WP_BUFFERS uint lightCount, float u) {
  float scaled = u * toFloat(lightCount);
  uint i = min(toUint(scaled), lightCount - 1u);
  GpuLight candidate = WP_LOAD(lights, i);
  return (scaled - toFloat(i)) < candidate.edge2.w ? i : candidate.info.x;
}

// Solid-angle density of sampling a given point on `light`, chosen with probability
// `selection`, from a point at squared distance `distanceSquared`, where cos(theta) at the
// light is cosAtLight.
WP_FN float lightPdf(GpuLight light, float selection, float distanceSquared, float cosAtLight) {
  return areaToSolidAnglePdf(selection / light.v0.w, distanceSquared, cosAtLight);
}

// A point uniform on the area of `light`, seen from `position` (selection not included),
// with the emission there: the emissive texture at the point's interpolated TEXCOORD_0.
WP_FN LightSample sampleLightTriangle(WP_BUFFERS GpuLight light, vec3 position, vec2 u) {
  vec2 b = sampleUniformTriangle(u);
  vec3 e1 = make_vec3(light.edge1.x, light.edge1.y, light.edge1.z);
  vec3 e2 = make_vec3(light.edge2.x, light.edge2.y, light.edge2.z);
  vec3 point = make_vec3(light.v0.x, light.v0.y, light.v0.z) + e1 * b.x + e2 * b.y;
  vec3 toLight = point - position;
  float distanceSquared = dot(toLight, toLight);
  LightSample s;
  s.distance = sqrt(distanceSquared);
  s.direction = s.distance > 0.0f ? toLight / s.distance : make_vec3(0.0f, 0.0f, 1.0f);
  vec3 n = cross(e1, e2);
  float cosAtLight = dot(n, s.direction) / length(n);
  s.pdf = s.distance > 0.0f ? areaToSolidAnglePdf(1.0f / light.v0.w, distanceSquared, cosAtLight) : 0.0f;
  vec3 emission = make_vec3(light.emission.x, light.emission.y, light.emission.z);
  if (light.info.w != WP_INVALID) {
    GpuTriangleShading shading = WP_LOAD(triangleShading, light.info.z);
    emission = texturedEmission(WP_BUFFERS_ARG emission, light.info.w, hasUv(shading), uvAt(shading, b));
  }
  s.radiance = emittedRadiance(emission, light.info.y != 0u, n, -s.direction);
  return s;
}

// ---- Selection by solid angle (WP_LIGHT_SELECTION_SOLID_ANGLE) ---------------------------
// The seed report's alternative to selection by power: a light is chosen with probability
// proportional to the solid angle it subtends from the shading point times its luminance,
// so near lights get the samples that far bright ones would take. It costs a pass over all
// lights per light sample (and per light hit, for the MIS weight), so it suits scenes with
// few emissive triangles; off by default. A textured light counts with its mean emission.

// Solid angle of triangle (a, b, c), as vectors from the viewpoint (Van Oosterom & Strackee
// 1983): tan(omega / 2) = |a.(b x c)| / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|). A
// negative denominator means omega / 2 > pi / 2; single-argument atan keeps it portable.
WP_FN float triangleSolidAngle(vec3 a, vec3 b, vec3 c) {
  float la = length(a);
  float lb = length(b);
  float lc = length(c);
  float numerator = fabs(dot(a, cross(b, c)));
  float denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  if (denominator == 0.0f) {
    return WP_PI;
  }
  float halfAngle = atan(numerator / denominator);
  return 2.0f * (denominator > 0.0f ? halfAngle : halfAngle + WP_PI);
}

// Selection weight of `light` from `position`: 0 where a one-sided light shows its back.
WP_FN float solidAngleWeight(GpuLight light, vec3 position) {
  vec3 e1 = make_vec3(light.edge1.x, light.edge1.y, light.edge1.z);
  vec3 e2 = make_vec3(light.edge2.x, light.edge2.y, light.edge2.z);
  vec3 a = make_vec3(light.v0.x, light.v0.y, light.v0.z) - position;
  if (light.info.y == 0u && dot(cross(e1, e2), a) >= 0.0f) {
    return 0.0f;
  }
  return triangleSolidAngle(a, a + e1, a + e2) * light.emission.w;
}

WP_FN float solidAngleWeightSum(WP_BUFFERS uint lightCount, vec3 position) {
  float sum = 0.0f;
  for (uint i = 0u; i < lightCount; ++i) {
    sum += solidAngleWeight(WP_LOAD(lights, i), position);
  }
  return sum;
}

// Probability that `light` is selected from `position` under `selection` (WP_LIGHT_SELECTION_*).
WP_FN float lightSelectionProbability(WP_BUFFERS uint lightCount, uint selection, GpuLight light,
                                      vec3 position) {
  if (selection != WP_LIGHT_SELECTION_SOLID_ANGLE) {
    return light.edge1.w;
  }
  float sum = solidAngleWeightSum(WP_BUFFERS_ARG lightCount, position);
  return sum > 0.0f ? solidAngleWeight(light, position) / sum : 0.0f;
}

WP_STRUCT(LightChoice)
  uint index;         // WP_INVALID: no light faces the shading point
  float probability;  // of choosing it
WP_STRUCT_END(LightChoice)

// The light that u in [0, 1) picks with probability proportional to solidAngleWeight: the
// last light with a positive weight whose running sum so far is at most u * sum, i.e.
// whose interval of the sum holds u * sum (rounding above the sum falls to the last one).
WP_FN LightChoice selectLightBySolidAngle(WP_BUFFERS uint lightCount, vec3 position, float u) {
  float sum = solidAngleWeightSum(WP_BUFFERS_ARG lightCount, position);
  float target = u * sum;
  LightChoice choice;
  choice.index = WP_INVALID;
  choice.probability = 0.0f;
  float running = 0.0f;
  for (uint i = 0u; i < lightCount; ++i) {
    float w = solidAngleWeight(WP_LOAD(lights, i), position);
    if (w > 0.0f && running <= target) {
      choice.index = i;
      choice.probability = w / sum;
    }
    running += w;
  }
  return choice;
}

// Chooses a light (by power through the alias table, or by solid angle) and a point on it:
// u.x selects, (u.y, u.z) place the point.
WP_FN LightSample sampleLight(WP_BUFFERS uint lightCount, uint selection, vec3 position,
                              vec3 u) {
  LightChoice choice;
  if (selection == WP_LIGHT_SELECTION_SOLID_ANGLE) {
    choice = selectLightBySolidAngle(WP_BUFFERS_ARG lightCount, position, u.x);
  } else {
    choice.index = selectLight(WP_BUFFERS_ARG lightCount, u.x);
    choice.probability = WP_LOAD(lights, choice.index).edge1.w;
  }
  LightSample s;
  if (choice.index == WP_INVALID) {
    s.direction = make_vec3(0.0f, 0.0f, 1.0f);
    s.distance = 0.0f;
    s.radiance = make_vec3(0.0f, 0.0f, 0.0f);
    s.pdf = 0.0f;
    return s;
  }
  s = sampleLightTriangle(WP_BUFFERS_ARG WP_LOAD(lights, choice.index), position, make_vec2(u.y, u.z));
  s.pdf *= choice.probability;
  return s;
}

WP_END

#endif
