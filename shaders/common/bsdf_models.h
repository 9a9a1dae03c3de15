// The BSDF lobes as pure functions (eval, sample, pdf): rough metal (GGX), plastic (GGX
// specular over normalized Disney diffuse) and rough glass (Beckmann reflection and
// refraction), each with a delta version at alpha < WP_DELTA_ALPHA.
#ifndef WP_BSDF_MODELS_H
#define WP_BSDF_MODELS_H

#include "fresnel.h"
#include "microfacet.h"
#include "sampling.h"

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

// ---- Metal: D F V with GGX, Schlick's F0 = base colour, Frostbite's V -------------------

WP_FN BsdfEval evalMetal(vec3 f0, float alpha, vec3 wo, vec3 wi) {
  float side = sideOf(wo);
  vec3 o = mirrorZ(wo, side);
  vec3 i = mirrorZ(wi, side);
  if (alpha < WP_DELTA_ALPHA || o.z < WP_BSDF_MIN_COS || i.z < WP_BSDF_MIN_COS) {
    return noEval();
  }
  HalfVector h = halfVectorOf(o, i);
  float cosOH = h.cosine;
  float d = ggxD(alpha, h.normal);
  BsdfEval e;
  e.fCos = fresnelSchlick(f0, cosOH) * (d * ggxVisibility(alpha, o.z, i.z) * i.z);
  // D(h) cos(theta_h) sampling, times the Jacobian of h -> wi = reflect(wo, h), 1 / (4 wo.h).
  e.pdf = d * h.normal.z / (4.0f * cosOH);
  return e;
}

WP_FN MaterialSample sampleMetal(vec3 f0, float alpha, vec3 wo, vec2 u) {
  float side = sideOf(wo);
  vec3 o = mirrorZ(wo, side);
  if (o.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  if (alpha < WP_DELTA_ALPHA) {
    return deltaSample(mirrorDirection(o), fresnelSchlick(f0, o.z), 1.0f, side);
  }
  vec3 wi = reflectAbout(o, sampleGgxNormal(alpha, u));
  if (wi.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  return sampleFromEval(wi, evalMetal(f0, alpha, o, wi), side);
}

// ---- Plastic: GGX specular coat over normalized Disney diffuse ---------------------------

// Burley 2012's diffuse retro-reflection with the renormalization of Lagarde & de Rousiers
// 2014 (listing 1), which keeps diffuse plus specular near unit albedo. `roughness` is
// perceptual; cosIH is the cosine between wi and the half vector. Symmetric in o and i.
WP_FN float disneyDiffuseFactor(float roughness, float cosO, float cosI, float cosIH) {
  float energyBias = 0.5f * roughness;
  float energyFactor = 1.0f + roughness * (1.0f / 1.51f - 1.0f);
  float fd90 = energyBias + 2.0f * cosIH * cosIH * roughness;
  float lightScatter = 1.0f + (fd90 - 1.0f) * schlickWeight(cosI);
  float viewScatter = 1.0f + (fd90 - 1.0f) * schlickWeight(cosO);
  return lightScatter * viewScatter * energyFactor;
}

// Monte Carlo Fresnel blending (the seed report's section 4.4): the specular lobe is picked
// with probability F / (F + (1 - F) luminance(albedo)), F = Schlick at cos(theta_o), i.e.
// by the Fresnel term weighted against the diffuse albedo, so a dark base does not waste
// samples on a lobe that returns little (for a white base it is F itself). It depends on
// wo alone, so the pdf of any wi is computable on the light-sampling side too.
WP_FN float plasticSpecularProbability(vec3 albedo, float f0, float cosO, uint flags) {
  if ((flags & WP_BSDF_FIXED_LOBE_CHOICE) != 0u) {
    return 0.5f;
  }
  float f = fresnelSchlickScalar(f0, cosO);
  float total = f + (1.0f - f) * luminance(albedo);
  return total > 0.0f ? f / total : 1.0f;
}

// f = D F(wi.h) V + albedo / pi * disney * (1 - F(cos_o)) (1 - F(cos_i)) / (1 - F_avg).
// The diffuse part is what the coat transmits on the way in and out; the product form
// keeps f reciprocal (a factor 1 - F(wi.h) alone lets a smooth plastic reflect up to twice
// the light at grazing angles), and dividing by 1 - F_avg (Kelemen & Szirmay-Kalos 2001)
// makes a white Lambertian base under a smooth coat reflect exactly 1.
WP_FN BsdfEval evalPlastic(vec3 albedo, float roughness, float ior, uint flags, vec3 wo, vec3 wi) {
  float side = sideOf(wo);
  vec3 o = mirrorZ(wo, side);
  vec3 i = mirrorZ(wi, side);
  if (o.z < WP_BSDF_MIN_COS || i.z < WP_BSDF_MIN_COS) {
    return noEval();
  }
  float alpha = alphaFromRoughness(roughness);
  float f0 = f0FromIor(ior);
  HalfVector h = halfVectorOf(o, i);
  float cosIH = h.cosine;
  float coat = (1.0f - fresnelSchlickScalar(f0, o.z)) * (1.0f - fresnelSchlickScalar(f0, i.z)) /
               (1.0f - fresnelSchlickAverage(f0));
  float diffuse = disneyDiffuseFactor(roughness, o.z, i.z, cosIH) * coat * WP_INV_PI;
  float specularProbability = plasticSpecularProbability(albedo, f0, o.z, flags);
  BsdfEval e;
  e.fCos = albedo * (diffuse * i.z);
  e.pdf = (1.0f - specularProbability) * cosineHemispherePdf(i.z);
  if (alpha >= WP_DELTA_ALPHA) {
    float d = ggxD(alpha, h.normal);
    float specular = d * fresnelSchlickScalar(f0, cosIH) * ggxVisibility(alpha, o.z, i.z);
    e.fCos = e.fCos + make_vec3(specular, specular, specular) * i.z;
    e.pdf += specularProbability * d * h.normal.z / (4.0f * cosIH);
  }
  return e;
}

// u.x picks the lobe, u.yz the direction.
WP_FN MaterialSample samplePlastic(vec3 albedo, float roughness, float ior, uint flags, vec3 wo, vec3 u) {
  float side = sideOf(wo);
  vec3 o = mirrorZ(wo, side);
  if (o.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  float alpha = alphaFromRoughness(roughness);
  float f0 = f0FromIor(ior);
  float specularProbability = plasticSpecularProbability(albedo, f0, o.z, flags);
  vec3 wi;
  if (u.x < specularProbability) {
    if (alpha < WP_DELTA_ALPHA) {
      float f = fresnelSchlickScalar(f0, o.z) / specularProbability;
      return deltaSample(mirrorDirection(o), make_vec3(f, f, f), specularProbability, side);
    }
    wi = reflectAbout(o, sampleGgxNormal(alpha, make_vec2(u.y, u.z)));
  } else {
    wi = sampleCosineHemisphere(make_vec2(u.y, u.z));
  }
  if (wi.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  return sampleFromEval(wi, evalPlastic(albedo, roughness, ior, flags, o, wi), side);
}

// ---- Rough glass: Walter et al. 2007 with Beckmann normals -------------------------------

// An index-matched interface does not bend light whatever its roughness, and the
// refraction Jacobian degenerates there, so it is treated as smooth.
WP_FN bool glassIsDelta(float alpha, float ior) { return alpha < WP_DELTA_ALPHA || fabs(ior - 1.0f) < 1e-3f; }

WP_FN float glassSamplingAlpha(float alpha, float cosO, uint flags) {
  return (flags & WP_BSDF_WIDEN_BECKMANN) != 0u ? widenedBeckmannAlpha(alpha, cosO) : alpha;
}

// Reflection f = F D G / (4 |cos_o| |cos_i|), untinted; refraction (radiance transport)
// f = tint (1 - F) D G |wo.m| |wi.m| / ((wo.m + eta wi.m)^2 |cos_o| |cos_i|), with the
// exact dielectric F and Smith's separable G = G1(wo) G1(wi), as in Walter et al. 2007.
// `ior` is n(inside) / n(outside); the tint (glTF's base colour) colours transmission.
WP_FN BsdfEval evalGlass(vec3 tint, float alpha, float ior, uint flags, vec3 wo, vec3 wi) {
  float side = sideOf(wo);
  float eta = side > 0.0f ? ior : 1.0f / ior;  // n(wi's side if refracted) / n(wo's side)
  vec3 o = mirrorZ(wo, side);
  vec3 i = mirrorZ(wi, side);
  if (glassIsDelta(alpha, ior) || o.z < WP_BSDF_MIN_COS || fabs(i.z) < WP_BSDF_MIN_COS) {
    return noEval();
  }
  float samplingAlpha = glassSamplingAlpha(alpha, o.z, flags);
  float g = beckmannG1(alpha, o.z) * beckmannG1(alpha, fabs(i.z));
  BsdfEval e;
  if (i.z > 0.0f) {
    HalfVector h = halfVectorOf(o, i);
    float f = fresnelDielectric(h.cosine, eta);
    float r = f * beckmannD(alpha, h.normal) * g / (4.0f * o.z);
    e.fCos = make_vec3(r, r, r);
    e.pdf = f * beckmannD(samplingAlpha, h.normal) * h.normal.z / (4.0f * h.cosine);
    return e;
  }
  // The generalized half vector of refraction, facing the macro normal.
  vec3 h = o + i * eta;
  float length2 = dot(h, h);
  if (length2 < 1e-12f) {
    return noEval();
  }
  vec3 m = h * ((h.z < 0.0f ? -1.0f : 1.0f) / sqrt(length2));
  float cosOM = dot(o, m);
  float cosIM = dot(i, m);
  if (cosOM <= 0.0f || cosIM >= 0.0f) {
    return noEval();  // no microfacet refracts wo into wi
  }
  float transmittance = 1.0f - fresnelDielectric(cosOM, eta);
  float denominator = cosOM + eta * cosIM;
  float denominator2 = denominator * denominator;
  e.fCos = tint * (transmittance * beckmannD(alpha, m) * g * cosOM * -cosIM / (denominator2 * o.z));
  // The Jacobian of m -> wi under refraction is eta^2 |wi.m| / (wo.m + eta wi.m)^2.
  e.pdf = transmittance * beckmannD(samplingAlpha, m) * m.z * eta * eta * -cosIM / denominator2;
  return e;
}

// u.x chooses reflection with the probability of the exact Fresnel term at the sampled
// microfacet, u.yz the microfacet normal.
WP_FN MaterialSample sampleGlass(vec3 tint, float alpha, float ior, uint flags, vec3 wo, vec3 u) {
  float side = sideOf(wo);
  float eta = side > 0.0f ? ior : 1.0f / ior;
  vec3 o = mirrorZ(wo, side);
  if (o.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  vec3 m = make_vec3(0.0f, 0.0f, 1.0f);
  bool isDelta = glassIsDelta(alpha, ior);
  if (!isDelta) {
    m = sampleBeckmannNormal(glassSamplingAlpha(alpha, o.z, flags), make_vec2(u.y, u.z));
  }
  float cosOM = dot(o, m);
  if (cosOM <= 0.0f) {
    return noSample();
  }
  float f = fresnelDielectric(cosOM, eta);
  bool reflected = u.x < f;
  vec3 wi = reflectAbout(o, m);
  if (!reflected) {
    wi = refractAbout(o, m, eta).direction;  // f < 1 here, so there is no total reflection
  }
  if (isDelta) {
    // f * |cos| / pdf: F / F for reflection, (1 - F) / eta^2 / (1 - F) for refraction.
    vec3 weight = reflected ? make_vec3(1.0f, 1.0f, 1.0f) : tint / (eta * eta);
    return deltaSample(wi, weight, reflected ? f : 1.0f - f, side);
  }
  if (reflected ? wi.z < WP_BSDF_MIN_COS : wi.z > -WP_BSDF_MIN_COS) {
    return noSample();
  }
  // Evaluated with the true wo: mirrored, it would lose which side the path is on.
  return sampleFromEval(wi, evalGlass(tint, alpha, ior, flags, wo, mirrorZ(wi, side)), side);
}

WP_END

#endif
