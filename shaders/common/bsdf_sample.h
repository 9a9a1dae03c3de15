// What every BSDF lobe shares: the eval and sample records, the conventions of the local
// frame, and the helpers that mirror directions into wo's hemisphere.
#ifndef WP_BSDF_SAMPLE_H
#define WP_BSDF_SAMPLE_H

#include "portable.h"

// Conventions shared by every lobe:
// - Directions are unit vectors in the local shading frame, z = the surface normal; wo points
//   towards the viewer, wi towards the light.
// - Opaque lobes (metal, plastic) are two-sided: they reflect into wo's hemisphere,
//   whichever side that is. Glass needs z = the outward normal (do not flip the frame
//   towards wo): wo.z < 0 means the path is inside, and the index ratio is swapped.
// - BsdfEval.fCos = f * |cos(theta_i)|; pdf is the solid-angle density with which the
//   matching sample function returns wi, 0 where it never does. Delta lobes (mirror,
//   Snell) contribute 0 to both: no direction fixed in advance can hit them.
// - Refraction follows pbrt's TransportMode::Radiance: camera paths carry radiance, which
//   is divided by eta^2 = (n_i / n_o)^2 when the path enters a denser medium (wi on the
//   side of index n_i, wo on n_o), because radiance / n^2 is what is conserved. So
//   f(wo, wi) / n_o^2 = f(wi, wo) / n_i^2 (generalized reciprocity).
// - Directions within WP_BSDF_MIN_COS of the horizon get f = pdf = 0 and fail to sample,
//   so no division by a vanishing cosine can produce inf or NaN.

#define WP_BSDF_MIN_COS 1e-6f

#define WP_SAMPLE_DELTA 1u         // wi is a delta direction: no MIS weight, no NEE
#define WP_SAMPLE_TRANSMISSION 2u  // wi is on the other side of the surface than wo

// Render switches passed as the `flags` argument; 0u is the default.
// WP_BSDF_WIDEN_BECKMANN: sample glass's Beckmann normals with Walter et al.'s widened
// alpha (microfacet.h). The seed report (section 4.7) counts this among its biased tricks,
// but here nothing is biased: f keeps the true alpha, and every pdf (the sample's, and
// evalMaterial's and pdfMaterial's for MIS on the light side) is the density of the widened
// distribution, so weights are f |cos| / pdf of what was actually sampled. Only the
// variance changes (smaller weight peaks at grazing angles). Pass the same flags to eval,
// sample and pdf, or MIS weights no longer sum to 1.
#define WP_BSDF_WIDEN_BECKMANN 1u
// WP_BSDF_FIXED_LOBE_CHOICE: plastic picks its specular and diffuse lobes 50/50 instead of by
// Fresnel (plasticSpecularProbability). Unbiased as well (the pdfs follow); it exists only
// to measure what Fresnel blending gains (README, "Materials and textures").
#define WP_BSDF_FIXED_LOBE_CHOICE 2u

WP_BEGIN

WP_STRUCT(BsdfEval)
  vec3 fCos;  // f(wo, wi) * |cos(theta_i)|
  float pdf;  // density of wi under the sampling routine, per solid angle
WP_STRUCT_END(BsdfEval)

WP_STRUCT(MaterialSample)
  vec3 wi;      // sampled incident direction (local)
  vec3 weight;  // f * |cos(theta_i)| / pdf (for delta lobes: the lobe's factor / pdf)
  float pdf;    // solid-angle density; for delta lobes the probability of the lobe; 0 = no sample
  uint flags;   // WP_SAMPLE_* bits
WP_STRUCT_END(MaterialSample)

WP_FN BsdfEval noEval() {
  BsdfEval e;
  e.fCos = make_vec3(0.0f, 0.0f, 0.0f);
  e.pdf = 0.0f;
  return e;
}

WP_FN MaterialSample noSample() {
  MaterialSample s;
  s.wi = make_vec3(0.0f, 0.0f, 1.0f);
  s.weight = make_vec3(0.0f, 0.0f, 0.0f);
  s.pdf = 0.0f;
  s.flags = 0u;
  return s;
}

// A non-delta sample in direction wi, its weight and pdf from the lobe's own eval.
WP_FN MaterialSample sampleFromEval(vec3 wi, BsdfEval e, float side) {
  if (!(e.pdf > 0.0f)) {
    return noSample();
  }
  MaterialSample s;
  s.wi = make_vec3(wi.x, wi.y, wi.z * side);
  s.weight = e.fCos / e.pdf;
  s.pdf = e.pdf;
  s.flags = wi.z < 0.0f ? WP_SAMPLE_TRANSMISSION : 0u;
  return s;
}

WP_FN MaterialSample deltaSample(vec3 wi, vec3 weight, float probability, float side) {
  MaterialSample s;
  s.wi = make_vec3(wi.x, wi.y, wi.z * side);
  s.weight = weight;
  s.pdf = probability;
  s.flags = WP_SAMPLE_DELTA | (wi.z < 0.0f ? WP_SAMPLE_TRANSMISSION : 0u);
  return s;
}

// +1 when wo is above the surface, -1 below: multiplying z by it mirrors both directions
// into wo's hemisphere, where each lobe is written.
WP_FN float sideOf(vec3 wo) { return wo.z < 0.0f ? -1.0f : 1.0f; }

WP_FN vec3 mirrorZ(vec3 v, float side) { return make_vec3(v.x, v.y, v.z * side); }

WP_FN vec3 mirrorDirection(vec3 wo) { return make_vec3(-wo.x, -wo.y, wo.z); }

WP_STRUCT(HalfVector)
  vec3 normal;   // the microfacet normal that reflects o into i
  float cosine;  // dot(o, normal) = dot(i, normal)
WP_STRUCT_END(HalfVector)

// The half vector of a reflection pair in the upper hemisphere. Its cosine is taken as
// |o + i| / 2 rather than a dot product, so it is the same float for (o, i) and (i, o):
// near the critical angle F's slope is unbounded, and two roundings would break
// reciprocity. |o + i| >= o.z + i.z > 0.
WP_FN HalfVector halfVectorOf(vec3 o, vec3 i) {
  vec3 sum = o + i;
  float len = length(sum);
  HalfVector h;
  h.normal = sum / len;
  h.cosine = 0.5f * len;
  return h;
}

WP_END

#endif
