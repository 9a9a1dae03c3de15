// Next event estimation on emissive triangles: power-proportional selection through an
// alias table, a point uniform on the chosen triangle, densities in solid angle.
#ifndef WP_LIGHTS_H
#define WP_LIGHTS_H

#include "layout.h"
#include "sampling.h"

WP_BEGIN

#ifdef WP_BUFFERS_AS_ARGUMENTS
#define WP_LIGHT_BUFFER WP_GLOBAL_PTR(GpuLight) lights,
#define WP_LIGHT_BUFFER_ARG lights,
#else
#define WP_LIGHT_BUFFER
#define WP_LIGHT_BUFFER_ARG
#endif

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
WP_FN uint selectLight(WP_LIGHT_BUFFER uint lightCount, float u) {
  float scaled = u * toFloat(lightCount);
  uint i = min(toUint(scaled), lightCount - 1u);
  GpuLight candidate = WP_LIGHT(i);
  return (scaled - toFloat(i)) < candidate.edge2.w ? i : candidate.info.x;
}

// Solid-angle density of sampling a given point on `light` (selection included) from a
// point at squared distance `distanceSquared`, where cos(theta) at the light is cosAtLight.
WP_FN float lightPdf(GpuLight light, float distanceSquared, float cosAtLight) {
  return areaToSolidAnglePdf(light.edge1.w / light.v0.w, distanceSquared, cosAtLight);
}

// A point uniform on the area of `light`, seen from `position` (selection not included).
WP_FN LightSample sampleLightTriangle(GpuLight light, vec3 position, vec2 u) {
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
  s.radiance = emittedRadiance(emission, light.info.y != 0u, n, -s.direction);
  return s;
}

// Chooses a light by power and a point on it: u.x selects, (u.y, u.z) place the point.
WP_FN LightSample sampleLight(WP_LIGHT_BUFFER uint lightCount, vec3 position, vec3 u) {
  GpuLight light = WP_LIGHT(selectLight(WP_LIGHT_BUFFER_ARG lightCount, u.x));
  LightSample s = sampleLightTriangle(light, position, make_vec2(u.y, u.z));
  s.pdf *= light.edge1.w;
  return s;
}

WP_END

#endif
