// Energy that single-scattering GGX loses, given back: the directional albedos of
// ggx_reflection.h (tabulated by tools/make_bsdf_tables.cpp), a multiple-scattering
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

#include "bsdf_table_lookup.h"
#include "fresnel.h"
#include "portable.h"
#include "sampling.h"

WP_BEGIN

// Directional albedo of evalGgxReflection with Schlick's curve from F0 to F90: F0 E +
// (F90 - F0) E_schlick, since the curve is linear in both. `roughness` is perceptual. For a
// coloured F0 the largest channel has the largest albedo at every angle (E >= E_schlick), so
// passing the largest F0 gives the largest channel's albedo.
WP_FN float ggxSpecularAlbedo(float f0, float f90, float roughness, float cosTheta) {
  BsdfTablePoint point = bsdfTablePoint(roughness, cosTheta);
  return f0 * bsdfTableAtPoint(WP_TABLE_GGX_WHITE, point) + (f90 - f0) * bsdfTableAtPoint(WP_TABLE_GGX_SCHLICK, point);
}

// Its hemispherical mean.
WP_FN float ggxSpecularMeanAlbedo(float f0, float f90, float roughness) {
  GgxMeanAlbedos means = ggxMeanAlbedos(roughness);
  return f0 * means.white + (f90 - f0) * means.schlick;
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
  float meanAlbedo = ggxMeanAlbedos(roughness).white;
  float lost = 1.0f - meanAlbedo;
  if (lost < 1e-4f) {
    return make_vec3(0.0f, 0.0f, 0.0f);  // smooth: nothing to give back, and 0 / 0 below
  }
  float shape = (1.0f - bsdfTableAt(WP_TABLE_GGX_WHITE, roughness, cosO)) *
                (1.0f - bsdfTableAt(WP_TABLE_GGX_WHITE, roughness, cosI)) / (WP_PI * lost);
  return multipleScatteringFresnel(f0, meanAlbedo) * shape;
}

// The share of a metal's reflected energy, seen from cos(theta_o), that the multiple-
// scattering lobe holds: (1 - E(o)) F_ms against E(o) F_avg, by luminance (for choosing
// which lobe to sample; any positive share would be unbiased).
WP_FN float ggxMultipleScatteringShare(vec3 f0, float roughness, float cosO) {
  float meanAlbedo = ggxMeanAlbedos(roughness).white;
  if (1.0f - meanAlbedo < 1e-4f) {
    return 0.0f;
  }
  float albedo = bsdfTableAt(WP_TABLE_GGX_WHITE, roughness, cosO);
  float single = albedo * luminance(fresnelSchlickAverage(f0));
  float multiple = (1.0f - albedo) * luminance(multipleScatteringFresnel(f0, meanAlbedo));
  return single + multiple > 0.0f ? multiple / (single + multiple) : 0.0f;
}

// ---- A diffuse base under a specular layer: albedo scaling ------------------------------

// The factor (1 - E_s(o)) (1 - E_s(i)) / (1 - E_s,avg) of a diffuse base under a GGX layer
// whose albedo, Fresnel F0 to F90 included, is E_s (of its largest channel, `f0` being the
// largest F0): light reaches the base with what the layer does not reflect, on the way in and
// out. For a white Lambertian base the two then reflect exactly 1 at every angle and
// roughness in the largest channel, at most 1 in the others (the base's share integrates to
// 1 - E_s(o)); the product form keeps it reciprocal. At roughness 0 E_s is Schlick's F itself.
WP_FN_INLINED float specularLayerTransmission(float f0, float f90, float roughness, float cosO, float cosI) {
  float meanAlbedo = ggxSpecularMeanAlbedo(f0, f90, roughness);
  return (1.0f - ggxSpecularAlbedo(f0, f90, roughness, cosO)) * (1.0f - ggxSpecularAlbedo(f0, f90, roughness, cosI)) /
         max(1.0f - meanAlbedo, 1e-6f);
}

WP_END

#endif
