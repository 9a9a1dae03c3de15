// BSDF evaluation, sampling and density. Directions are in the local shading frame (z =
// normal, oriented towards the outgoing direction wo).
#ifndef WP_BSDF_H
#define WP_BSDF_H

#include "layout.h"
#include "sampling.h"

WP_BEGIN

WP_STRUCT(BsdfSample)
  vec3 wi;      // sampled incident direction (local)
  vec3 weight;  // f * |cos(theta_i)| / pdf
  float pdf;    // solid-angle density; 0 means no valid sample
WP_STRUCT_END(BsdfSample)

// f * |cos(theta_i)| for outgoing wo and incident wi (Lambert: albedo / pi).
WP_FN vec3 bsdfEvalCos(GpuMaterial m, vec3 wo, vec3 wi) {
  vec3 albedo = make_vec3(m.baseColor.x, m.baseColor.y, m.baseColor.z);
  return (wo.z > 0.0f && wi.z > 0.0f) ? albedo * (wi.z * WP_INV_PI) : make_vec3(0.0f, 0.0f, 0.0f);
}

// Density with which bsdfSample picks wi.
WP_FN float bsdfPdf(GpuMaterial m, vec3 wo, vec3 wi) {
  return (wo.z > 0.0f) ? cosineHemispherePdf(wi.z) : 0.0f;
}

WP_FN BsdfSample bsdfSample(GpuMaterial m, vec3 wo, vec2 u) {
  BsdfSample s;
  s.wi = sampleCosineHemisphere(u);
  s.pdf = bsdfPdf(m, wo, s.wi);
  s.weight = s.pdf > 0.0f ? bsdfEvalCos(m, wo, s.wi) / s.pdf : make_vec3(0.0f, 0.0f, 0.0f);
  return s;
}

WP_END

#endif
