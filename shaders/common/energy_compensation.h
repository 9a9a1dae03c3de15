// Energy that single-scattering GGX loses, given back: the directional albedos of
// ggx_reflection.h (tabulated by tools/make_ggx_albedo_table.cpp), a multiple-scattering
// lobe for metals and the albedo scaling of a diffuse base under a specular layer, both after
// Kulla & Conty 2017, "Revisiting Physically Based Shading at Imageworks".
//
// Why: a GGX facet reflects a ray once, so light that would bounce between facets is lost:
// a white metal of roughness 1 seen head-on reflects 31% (1 - ln 2), a white glTF dielectric
// over a sphere 93%. glTF's BRDF is written as single scattering, but a white material that
// turns grey as it gets rough is not what an author means, nor what Cycles' multiscatter GGX
// shows.
#ifndef WP_ENERGY_COMPENSATION_H
#define WP_ENERGY_COMPENSATION_H

#include "fresnel.h"
#include "portable.h"
#include "sampling.h"

// Element i of the tables: C++ and OpenCL read the constant array of ggx_albedo_table.h;
// GLSL (shaders/vulkan/bindings.glsl) fetches the copy the host uploads from that array.
#ifdef WP_BUFFERS_AS_ARGUMENTS
#include "ggx_albedo_table.h"
#define WP_GGX_ALBEDO(i) kGgxAlbedo[i]
#endif

WP_BEGIN

#define WP_GGX_TABLE_SIZE 32u
#define WP_GGX_TABLE_WHITE 0u            // E(cos, r) with F = 1
#define WP_GGX_TABLE_SCHLICK 1024u       // E(cos, r) with F = Schlick's weight (1 - i.h)^5
#define WP_GGX_TABLE_WHITE_MEAN 2048u    // E_avg(r) = 2 int E mu dmu, F = 1
#define WP_GGX_TABLE_SCHLICK_MEAN 2080u  // the same with Schlick's weight

// Bilinear interpolation of a table whose rows are roughness and columns cos(theta), both
// on j / (N - 1).
WP_FN float ggxTableAt(uint table, float roughness, float cosTheta) {
  float last = toFloat(WP_GGX_TABLE_SIZE - 1u);
  float x = clamp(cosTheta, 0.0f, 1.0f) * last;
  float y = clamp(roughness, 0.0f, 1.0f) * last;
  uint column = min(toUint(x), WP_GGX_TABLE_SIZE - 2u);
  uint row = min(toUint(y), WP_GGX_TABLE_SIZE - 2u);
  float fx = x - toFloat(column);
  float fy = y - toFloat(row);
  uint i = table + row * WP_GGX_TABLE_SIZE + column;
  float below = mix(WP_GGX_ALBEDO(i), WP_GGX_ALBEDO(i + 1u), fx);
  float above = mix(WP_GGX_ALBEDO(i + WP_GGX_TABLE_SIZE), WP_GGX_ALBEDO(i + WP_GGX_TABLE_SIZE + 1u), fx);
  return mix(below, above, fy);
}

// Linear interpolation of a per-roughness table.
WP_FN float ggxMeanAt(uint table, float roughness) {
  float y = clamp(roughness, 0.0f, 1.0f) * toFloat(WP_GGX_TABLE_SIZE - 1u);
  uint row = min(toUint(y), WP_GGX_TABLE_SIZE - 2u);
  return mix(WP_GGX_ALBEDO(table + row), WP_GGX_ALBEDO(table + row + 1u), y - toFloat(row));
}

// Directional albedo of evalGgxReflection with a scalar F0: F0 E + (1 - F0) E_schlick,
// since Schlick's F is linear in F0. `roughness` is perceptual.
WP_FN float ggxSpecularAlbedo(float f0, float roughness, float cosTheta) {
  return f0 * ggxTableAt(WP_GGX_TABLE_WHITE, roughness, cosTheta) +
         (1.0f - f0) * ggxTableAt(WP_GGX_TABLE_SCHLICK, roughness, cosTheta);
}

// Its hemispherical mean.
WP_FN float ggxSpecularMeanAlbedo(float f0, float roughness) {
  return f0 * ggxMeanAt(WP_GGX_TABLE_WHITE_MEAN, roughness) + (1.0f - f0) * ggxMeanAt(WP_GGX_TABLE_SCHLICK_MEAN, roughness);
}

// ---- Metal: the multiple-scattering lobe -------------------------------------------------

// F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)): the colour of light that bounced between
// facets more than once, each bounce weighted by the mean Fresnel F_avg = F0 + (1 - F0) / 21
// of Schlick's curve, summed as a geometric series. A white metal gets F_ms = 1.
WP_FN vec3 multipleScatteringFresnel(vec3 f0, float meanAlbedo) {
  vec3 meanFresnel = fresnelSchlickAverage(f0);
  return meanFresnel * meanFresnel * meanAlbedo / (make_vec3(1.0f, 1.0f, 1.0f) - meanFresnel * (1.0f - meanAlbedo));
}

// f_ms = F_ms (1 - E(o)) (1 - E(i)) / (pi (1 - E_avg)), E with F = 1: reflects 1 - E(o) of
// the light a white metal loses, with the shape of that loss (it grows towards grazing
// angles and with roughness), and is reciprocal; a white metal then reflects exactly
// everything. Returns f (without the cosine).
WP_FN vec3 ggxMultipleScattering(vec3 f0, float roughness, float cosO, float cosI) {
  float meanAlbedo = ggxMeanAt(WP_GGX_TABLE_WHITE_MEAN, roughness);
  float lost = 1.0f - meanAlbedo;
  if (lost < 1e-4f) {
    return make_vec3(0.0f, 0.0f, 0.0f);  // smooth: nothing to give back, and 0 / 0 below
  }
  float shape = (1.0f - ggxTableAt(WP_GGX_TABLE_WHITE, roughness, cosO)) *
                (1.0f - ggxTableAt(WP_GGX_TABLE_WHITE, roughness, cosI)) / (WP_PI * lost);
  return multipleScatteringFresnel(f0, meanAlbedo) * shape;
}

// The share of a metal's reflected energy, seen from cos(theta_o), that the multiple-
// scattering lobe holds: (1 - E(o)) F_ms against E(o) F_avg, by luminance (for choosing
// which lobe to sample; any positive share would be unbiased).
WP_FN float ggxMultipleScatteringShare(vec3 f0, float roughness, float cosO) {
  float meanAlbedo = ggxMeanAt(WP_GGX_TABLE_WHITE_MEAN, roughness);
  if (1.0f - meanAlbedo < 1e-4f) {
    return 0.0f;
  }
  float albedo = ggxTableAt(WP_GGX_TABLE_WHITE, roughness, cosO);
  float single = albedo * luminance(fresnelSchlickAverage(f0));
  float multiple = (1.0f - albedo) * luminance(multipleScatteringFresnel(f0, meanAlbedo));
  return single + multiple > 0.0f ? multiple / (single + multiple) : 0.0f;
}

// ---- A diffuse base under a specular layer: albedo scaling ------------------------------

// The factor (1 - E_s(o)) (1 - E_s(i)) / (1 - E_s,avg) of a diffuse base under a GGX layer
// whose albedo, Fresnel F0 included, is E_s: light reaches the base with what the layer does
// not reflect, on the way in and out. For a white Lambertian base the two then reflect
// exactly 1 at every angle and roughness (the base's share integrates to 1 - E_s(o)); the
// product form keeps it reciprocal. At roughness 0 E_s is Schlick's F itself.
WP_FN float specularLayerTransmission(float f0, float roughness, float cosO, float cosI) {
  float meanAlbedo = ggxSpecularMeanAlbedo(f0, roughness);
  return (1.0f - ggxSpecularAlbedo(f0, roughness, cosO)) * (1.0f - ggxSpecularAlbedo(f0, roughness, cosI)) /
         (1.0f - meanAlbedo);
}

WP_END

#endif
