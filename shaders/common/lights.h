// Next event estimation on the light table: emissive triangles and glTF punctual lights
// (KHR_lights_punctual), chosen in proportion to power through an alias table (or by solid
// angle); a point uniform on a chosen triangle, densities in solid angle; punctual lights are
// delta lights, which only this sampling can find.
#ifndef WP_LIGHTS_H
#define WP_LIGHTS_H

#include "binding_table.h"
#include "sampling.h"
#include "surface.h"
#include "texture.h"

WP_BEGIN

WP_STRUCT(LightSample)
  vec3 direction;  // unit, from the shading point towards the sampled point
  float distance;  // to the sampled point (WP_FLT_MAX: at infinity)
  vec3 radiance;   // emitted towards the shading point (0 behind a one-sided light); from a
                   // delta light, the irradiance it gives a surface facing it
  float pdf;       // solid-angle density, selection probability included; from a delta light
                   // the selection probability alone; 0: no sample
  bool isDelta;    // a punctual light: no BSDF sample can hit it, so no MIS weight
WP_STRUCT_END(LightSample)

WP_FN LightSample noLightSample() {
  LightSample s;
  s.direction = make_vec3(0.0f, 0.0f, 1.0f);
  s.distance = 0.0f;
  s.radiance = make_vec3(0.0f, 0.0f, 0.0f);
  s.pdf = 0.0f;
  s.isDelta = false;
  return s;
}

// ---- What a GpuLight holds (layout.h) ----------------------------------------------------

WP_FN uint lightKind(GpuLight light) { return light.info.y & WP_LIGHT_KIND_MASK; }
// Whether `light` is an emissive triangle rather than a punctual light. In a scene with lights
// of one kind (WP_SCENE_EMISSIVE, WP_SCENE_PUNCTUAL) Vulkan and OpenCL know the answer when they
// compile, and the other kind's code compiles away (lavapipe would run both sides).
WP_FN bool isTriangleLight(GpuLight light) {
  return WP_SCENE_EMISSIVE && (!WP_SCENE_PUNCTUAL || lightKind(light) == WP_LIGHT_TRIANGLE);
}
WP_FN bool lightIsDoubleSided(GpuLight light) { return (light.info.y & WP_LIGHT_DOUBLE_SIDED) != 0u; }
WP_FN float lightSelectionWeight(GpuLight light) { return light.emission.w; }
WP_FN float lightPowerProbability(GpuLight light) { return light.edge1.w; }
WP_FN float lightAliasThreshold(GpuLight light) { return light.edge2.w; }
WP_FN uint lightAlias(GpuLight light) { return light.info.x; }
WP_FN vec3 lightEmission(GpuLight light) { return make_vec3(light.emission.x, light.emission.y, light.emission.z); }

WP_FN vec3 triangleLightVertex(GpuLight light) { return make_vec3(light.v0.x, light.v0.y, light.v0.z); }
WP_FN vec3 triangleLightEdge1(GpuLight light) { return make_vec3(light.edge1.x, light.edge1.y, light.edge1.z); }
WP_FN vec3 triangleLightEdge2(GpuLight light) { return make_vec3(light.edge2.x, light.edge2.y, light.edge2.z); }
WP_FN float triangleLightArea(GpuLight light) { return light.v0.w; }
WP_FN uint triangleLightShading(GpuLight light) { return light.info.z; }
// The emitter's emissive texture, read as none where no material has one (as the material's,
// layout.h).
WP_FN uint triangleLightTexture(GpuLight light) { return WP_SCENE_EMISSIVE_TEXTURE ? light.info.w : WP_INVALID; }

WP_FN vec3 punctualPositionAtOpen(GpuLight light) { return make_vec3(light.v0.x, light.v0.y, light.v0.z); }
WP_FN vec3 punctualPositionAtClose(GpuLight light) { return make_vec3(light.edge2.x, light.edge2.y, light.edge2.z); }
WP_FN vec3 punctualDirectionAtOpen(GpuLight light) { return make_vec3(light.edge1.x, light.edge1.y, light.edge1.z); }
WP_FN vec3 punctualDirectionAtClose(GpuLight light) {
  return make_vec3(light.motion.x, light.motion.y, light.motion.z);
}
WP_FN float spotCosOuter(GpuLight light) { return light.v0.w; }
WP_FN float spotCosInner(GpuLight light) { return light.motion.w; }

// An emissive triangle (v0, v1, v2) of area `area`, emitting `emission` (one-sided unless
// doubleSided) with selection weight `weight` (GpuLight.emission.w), whose shading record
// and emissive texture are `shading` and `texture`. packScene fills in the alias table.
WP_FN GpuLight makeTriangleLight(vec3 v0, vec3 v1, vec3 v2, float area, vec3 emission, float weight,
                                 bool doubleSided, uint shading, uint texture) {
  vec3 edge1 = v1 - v0;
  vec3 edge2 = v2 - v0;
  GpuLight light;
  light.v0 = make_vec4(v0.x, v0.y, v0.z, area);
  light.edge1 = make_vec4(edge1.x, edge1.y, edge1.z, 0.0f);
  light.edge2 = make_vec4(edge2.x, edge2.y, edge2.z, 0.0f);
  light.emission = make_vec4(emission.x, emission.y, emission.z, weight);
  light.motion = make_vec4(0.0f, 0.0f, 0.0f, 0.0f);
  light.info = make_uvec4(0u, WP_LIGHT_TRIANGLE | (doubleSided ? WP_LIGHT_DOUBLE_SIDED : 0u), shading, texture);
  return light;
}

// A punctual light of kind `kind` (WP_LIGHT_POINT, _SPOT or _DIRECTIONAL) where it is and
// where it points at shutter open and close, with a spot's cone cosines, its intensity (or
// irradiance) and selection weight. packScene fills in the alias table.
WP_FN GpuLight makePunctualLight(uint kind, vec3 positionAtOpen, vec3 positionAtClose, vec3 directionAtOpen,
                                 vec3 directionAtClose, float cosOuter, float cosInner, vec3 intensity,
                                 float weight) {
  GpuLight light;
  light.v0 = make_vec4(positionAtOpen.x, positionAtOpen.y, positionAtOpen.z, cosOuter);
  light.edge1 = make_vec4(directionAtOpen.x, directionAtOpen.y, directionAtOpen.z, 0.0f);
  light.edge2 = make_vec4(positionAtClose.x, positionAtClose.y, positionAtClose.z, 0.0f);
  light.emission = make_vec4(intensity.x, intensity.y, intensity.z, weight);
  light.motion = make_vec4(directionAtClose.x, directionAtClose.y, directionAtClose.z, cosInner);
  light.info = make_uvec4(0u, kind, WP_INVALID, WP_INVALID);
  return light;
}

// The light with its probability of being selected by power, and its alias-table entry:
// keep it if the fraction of u * n is below `threshold`, else take light `alias`.
WP_FN GpuLight withPowerProbability(GpuLight light, float probability) {
  light.edge1.w = probability;
  return light;
}
WP_FN GpuLight withAliasEntry(GpuLight light, float threshold, uint alias) {
  light.edge2.w = threshold;
  light.info.x = alias;
  return light;
}

// A punctual light's position at shutter time u in [0, 1): straight from its place at
// shutter open to its place at close, as instances translate (motion.h).
WP_FN vec3 punctualPosition(GpuLight light, float time) {
  vec3 open = punctualPositionAtOpen(light);
  vec3 close = punctualPositionAtClose(light);
  return open + (close - open) * time;
}

// The unit direction a spot or directional light points at shutter time u: the two ends
// interpolated and normalized (exact at the ends; for a light that turns during the shutter,
// close to the slerp of the turn).
WP_FN vec3 punctualDirection(GpuLight light, float time) {
  vec3 open = punctualDirectionAtOpen(light);
  vec3 close = punctualDirectionAtClose(light);
  return normalize(open + (close - open) * time);
}

// KHR_lights_punctual's smooth spot falloff: (clamp((cos - cos_outer) / (cos_inner -
// cos_outer)), 0, 1))^2, the difference kept from vanishing as the extension's sample code
// keeps it. `cosAngle` is the cosine between the spot's direction and the direction to the
// lit point.
WP_FN float spotFalloff(GpuLight light, float cosAngle) {
  float cosOuter = spotCosOuter(light);
  float cosInner = spotCosInner(light);
  float t = clamp((cosAngle - cosOuter) / max(cosInner - cosOuter, 1e-3f), 0.0f, 1.0f);
  return t * t;
}

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
  return (scaled - toFloat(i)) < lightAliasThreshold(candidate) ? i : lightAlias(candidate);
}

// Solid-angle density of sampling a given point on `light`, chosen with probability
// `selection`, from a point at squared distance `distanceSquared`, where cos(theta) at the
// light is cosAtLight.
WP_FN float lightPdf(GpuLight light, float selection, float distanceSquared, float cosAtLight) {
  return areaToSolidAnglePdf(selection / triangleLightArea(light), distanceSquared, cosAtLight);
}

// A point uniform on the area of `light`, seen from `position` (selection not included),
// with the emission there: the emissive texture at the point's interpolated TEXCOORD_0.
WP_FN_INLINED LightSample sampleLightTriangle(WP_BUFFERS GpuLight light, vec3 position, vec2 u) {
  vec2 b = sampleUniformTriangle(u);
  vec3 e1 = triangleLightEdge1(light);
  vec3 e2 = triangleLightEdge2(light);
  vec3 point = triangleLightVertex(light) + e1 * b.x + e2 * b.y;
  vec3 toLight = point - position;
  float distanceSquared = dot(toLight, toLight);
  LightSample s = noLightSample();
  s.distance = sqrt(distanceSquared);
  s.direction = s.distance > 0.0f ? toLight / s.distance : make_vec3(0.0f, 0.0f, 1.0f);
  vec3 n = cross(e1, e2);
  float cosAtLight = dot(n, s.direction) / length(n);
  s.pdf = s.distance > 0.0f ? areaToSolidAnglePdf(1.0f / triangleLightArea(light), distanceSquared, cosAtLight) : 0.0f;
  vec3 emission = lightEmission(light);
  if (triangleLightTexture(light) != WP_INVALID) {
    GpuTriangleShading shading = WP_LOAD(triangleShading, triangleLightShading(light));
    emission = texturedEmission(WP_BUFFERS_ARG emission, triangleLightTexture(light), texCoordsAt(shading, b));
  }
  s.radiance = emittedRadiance(emission, lightIsDoubleSided(light), n, -s.direction);
  return s;
}

// What a punctual light gives `position` at shutter time `time` (selection not included):
// a point light I / r^2, a spot that times its falloff, a directional light its irradiance
// E from the direction opposite to where it points, at infinity. Intensities are W/sr and
// W/m^2 (KHR_lights_punctual's candela and lux / 683, as Blender converts them).
WP_FN LightSample samplePunctualLight(GpuLight light, vec3 position, float time) {
  LightSample s = noLightSample();
  s.isDelta = true;
  s.pdf = 1.0f;
  uint kind = lightKind(light);
  if (kind == WP_LIGHT_DIRECTIONAL) {
    s.direction = -punctualDirection(light, time);
    s.distance = WP_FLT_MAX;
    s.radiance = lightEmission(light);
    return s;
  }
  vec3 toLight = punctualPosition(light, time) - position;
  float distanceSquared = dot(toLight, toLight);
  if (!(distanceSquared > 0.0f)) {
    return noLightSample();
  }
  s.distance = sqrt(distanceSquared);
  s.direction = toLight / s.distance;
  float falloff = kind == WP_LIGHT_SPOT ? spotFalloff(light, -dot(punctualDirection(light, time), s.direction)) : 1.0f;
  s.radiance = lightEmission(light) * (falloff / distanceSquared);
  return s;
}

// ---- Selection by solid angle (WP_LIGHT_SELECTION_SOLID_ANGLE) ---------------------------
// The seed report's alternative to selection by power: a light is chosen with probability
// proportional to the solid angle it subtends from the shading point times its luminance,
// so near lights get the samples that far bright ones would take. It costs a pass over all
// lights per light sample (and per light hit, for the MIS weight), so it suits scenes with
// few emissive triangles; off by default. A textured light counts with its mean emission. A
// punctual light has no solid angle: it counts with the irradiance it gives the point (I / r^2
// times a spot's falloff, or a sun's E), what a small triangle's solid angle times its
// radiance tends to.

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

// Selection weight of `light` from `position` at shutter time `time`: 0 where a one-sided
// light shows its back.
WP_FN float solidAngleWeight(GpuLight light, vec3 position, float time) {
  if (!isTriangleLight(light)) {
    LightSample s = samplePunctualLight(light, position, time);
    return s.pdf > 0.0f ? luminance(s.radiance) : 0.0f;
  }
  vec3 e1 = triangleLightEdge1(light);
  vec3 e2 = triangleLightEdge2(light);
  vec3 a = triangleLightVertex(light) - position;
  if (!lightIsDoubleSided(light) && dot(cross(e1, e2), a) >= 0.0f) {
    return 0.0f;
  }
  return triangleSolidAngle(a, a + e1, a + e2) * lightSelectionWeight(light);
}

WP_FN float solidAngleWeightSum(WP_BUFFERS uint lightCount, vec3 position, float time) {
  float sum = 0.0f;
  for (uint i = 0u; i < lightCount; ++i) {
    sum += solidAngleWeight(WP_LOAD(lights, i), position, time);
  }
  return sum;
}

// Probability that `light` is selected from `position` at shutter time `time` under
// `selection` (WP_LIGHT_SELECTION_*).
WP_FN float lightSelectionProbability(WP_BUFFERS uint lightCount, uint selection, GpuLight light,
                                      vec3 position, float time) {
  if (!WP_RENDER_SOLID_ANGLE_SELECTION || selection != WP_LIGHT_SELECTION_SOLID_ANGLE) {
    return lightPowerProbability(light);
  }
  float sum = solidAngleWeightSum(WP_BUFFERS_ARG lightCount, position, time);
  return sum > 0.0f ? solidAngleWeight(light, position, time) / sum : 0.0f;
}

WP_STRUCT(LightChoice)
  uint index;         // WP_INVALID: no light faces the shading point
  float probability;  // of choosing it
WP_STRUCT_END(LightChoice)

// The light that u in [0, 1) picks with probability proportional to solidAngleWeight: the
// last light with a positive weight whose running sum so far is at most u * sum, i.e.
// whose interval of the sum holds u * sum (rounding above the sum falls to the last one).
WP_FN LightChoice selectLightBySolidAngle(WP_BUFFERS uint lightCount, vec3 position, float time, float u) {
  float sum = solidAngleWeightSum(WP_BUFFERS_ARG lightCount, position, time);
  float target = u * sum;
  LightChoice choice;
  choice.index = WP_INVALID;
  choice.probability = 0.0f;
  float running = 0.0f;
  for (uint i = 0u; i < lightCount; ++i) {
    float w = solidAngleWeight(WP_LOAD(lights, i), position, time);
    if (w > 0.0f && running <= target) {
      choice.index = i;
      choice.probability = w / sum;
    }
    running += w;
  }
  return choice;
}

// Chooses a light (by power through the alias table, or by solid angle) and a point on it,
// as seen from `position` at shutter time `time`: u.x selects, (u.y, u.z) place the point on
// a triangle.
WP_FN_INLINED LightSample sampleLight(WP_BUFFERS uint lightCount, uint selection, vec3 position,
                                      float time, vec3 u) {
  LightChoice choice;
  // (WP_RENDER_SOLID_ANGLE_SELECTION false: selection is power, and Vulkan and OpenCL compile the
  // solid-angle loops away.)
  if (WP_RENDER_SOLID_ANGLE_SELECTION && selection == WP_LIGHT_SELECTION_SOLID_ANGLE) {
    choice = selectLightBySolidAngle(WP_BUFFERS_ARG lightCount, position, time, u.x);
  } else {
    choice.index = selectLight(WP_BUFFERS_ARG lightCount, u.x);
    choice.probability = lightPowerProbability(WP_LOAD(lights, choice.index));
  }
  if (choice.index == WP_INVALID) {
    return noLightSample();
  }
  GpuLight light = WP_LOAD(lights, choice.index);
  // (A scene with neither kind of light samples none: WP_SCENE_PUNCTUAL false compiles the
  // punctual sampling away there too.)
  LightSample s = noLightSample();
  if (isTriangleLight(light)) {
    s = sampleLightTriangle(WP_BUFFERS_ARG light, position, make_vec2(u.y, u.z));
  } else if (WP_SCENE_PUNCTUAL) {
    s = samplePunctualLight(light, position, time);
  }
  s.pdf *= choice.probability;
  return s;
}

WP_END

#endif
