// The BSDF lobes as pure functions (eval, sample, pdf): rough metal (GGX), plastic (GGX
// specular over a Lambertian or normalized Disney diffuse base) and rough glass (Beckmann
// reflection and refraction), each with a delta version at alpha < WP_DELTA_ALPHA. Metal
// and plastic keep the energy that single-scattering GGX loses (energy_compensation.h).
#ifndef WP_BSDF_MODELS_H
#define WP_BSDF_MODELS_H

#include "bsdf_sample.h"
#include "energy_compensation.h"
#include "fresnel.h"
#include "ggx_reflection.h"
#include "microfacet.h"
#include "sampling.h"

WP_BEGIN

// ---- Metal: GGX with Schlick's F0 = base colour, plus its multiple scattering ------------

// f = F D V (ggx_reflection.h) + f_ms (energy_compensation.h), sampled as a one-sample mix:
// visible GGX normals, or the cosine for the multiple-scattering lobe with the probability of
// its share of the energy. `roughness` is perceptual.
WP_FN BsdfEval evalMetal(vec3 f0, float roughness, vec3 wo, vec3 wi) {
  float side = sideOf(wo);
  vec3 o = mirrorZ(wo, side);
  vec3 i = mirrorZ(wi, side);
  float alpha = alphaFromRoughness(roughness);
  if (alpha < WP_DELTA_ALPHA || o.z < WP_BSDF_MIN_COS || i.z < WP_BSDF_MIN_COS) {
    return noEval();
  }
  BsdfEval single = evalGgxReflection(f0, 1.0f, alpha, o, i);
  float multipleShare = ggxMultipleScatteringShare(f0, roughness, o.z);
  BsdfEval e;
  e.fCos = single.fCos + ggxMultipleScattering(f0, roughness, o.z, i.z) * i.z;
  e.pdf = (1.0f - multipleShare) * single.pdf + multipleShare * cosineHemispherePdf(i.z);
  return e;
}

// u.x picks the lobe, u.yz the direction.
WP_FN MaterialSample sampleMetal(vec3 f0, float roughness, vec3 wo, vec3 u) {
  float side = sideOf(wo);
  vec3 o = mirrorZ(wo, side);
  if (o.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  float alpha = alphaFromRoughness(roughness);
  if (alpha < WP_DELTA_ALPHA) {
    return deltaSample(mirrorDirection(o), fresnelSchlick(f0, o.z), 1.0f, side);
  }
  vec3 wi = u.x < ggxMultipleScatteringShare(f0, roughness, o.z) ? sampleCosineHemisphere(make_vec2(u.y, u.z))
                                                                    : sampleGgxReflection(alpha, o, make_vec2(u.y, u.z));
  if (wi.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  return sampleFromEval(wi, evalMetal(f0, roughness, o, wi), side);
}

// ---- Plastic: glTF's dielectric, a GGX specular layer over a diffuse base ----------------

// Burley 2012's diffuse retro-reflection with the renormalization of Lagarde & de Rousiers
// 2014 (listing 1), the seed report's diffuse: a material opts in with the extra
// "diffuse": "disney" (it reflects 1/1.51 of a Lambertian base at roughness 1). `roughness`
// is perceptual; cosIH is the cosine between wi and the half vector. Symmetric in o and i.
WP_FN float disneyDiffuseFactor(float roughness, float cosO, float cosI, float cosIH) {
  float energyBias = 0.5f * roughness;
  float energyFactor = 1.0f + roughness * (1.0f / 1.51f - 1.0f);
  float fd90 = energyBias + 2.0f * cosIH * cosIH * roughness;
  float lightScatter = 1.0f + (fd90 - 1.0f) * schlickWeight(cosI);
  float viewScatter = 1.0f + (fd90 - 1.0f) * schlickWeight(cosO);
  return lightScatter * viewScatter * energyFactor;
}

// The specular layer of glTF's dielectric: Schlick's curve from F0 at normal incidence to F90
// at grazing. KHR_materials_specular tints F0 by specularColor and scales both by the
// specular weight; without it specularColor and the weight are 1 and F0 comes from the IOR.
WP_STRUCT(SpecularLayer)
  vec3 f0;
  float f90;
WP_STRUCT_END(SpecularLayer)

WP_FN SpecularLayer dielectricSpecular(float ior, vec3 specularColor, float specularWeight) {
  SpecularLayer layer;
  vec3 tinted = specularColor * f0FromIor(ior);
  layer.f0 = min(tinted, make_vec3(1.0f, 1.0f, 1.0f)) * specularWeight;
  layer.f90 = specularWeight;
  return layer;
}

// The largest channel's F0, whose albedo is the layer's largest (energy_compensation.h).
WP_FN float largestF0(SpecularLayer layer) { return max(layer.f0.x, max(layer.f0.y, layer.f0.z)); }

// Monte Carlo Fresnel blending (the seed report's section 4.4): the specular lobe is picked
// with probability E / (E + (1 - E) luminance(albedo)), E the specular layer's directional
// albedo at cos(theta_o) (Schlick's F itself when smooth), i.e. by what the layer reflects
// weighted against what the base returns, so a dark base does not waste samples on a lobe
// that returns little. It depends on wo alone, so the pdf of any wi is computable on the
// light-sampling side too.
WP_FN float plasticSpecularProbability(vec3 albedo, SpecularLayer layer, float roughness, float cosO, uint flags) {
  if ((flags & WP_BSDF_FIXED_LOBE_CHOICE) != 0u) {
    return 0.5f;
  }
  float e = ggxSpecularAlbedo(largestF0(layer), layer.f90, roughness, cosO);
  float total = e + (1.0f - e) * luminance(albedo);
  return total > 0.0f ? e / total : 1.0f;
}

// glTF 2.0's dielectric_brdf (Appendix B): f = F(i.h) D V + albedo / pi * T(o, i), the
// specular layer over a Lambertian base (or the Disney one, `disneyBase`). glTF mixes the two
// by F(i.h); here the base gets T = specularLayerTransmission, the energy the layer does not
// reflect on the way in and out (energy_compensation.h), which keeps f reciprocal and a
// white base at albedo exactly 1 at every roughness, where the spec's mix gives a smooth
// surface up to twice the light at grazing angles and a rough one 7% too little.
WP_FN_INLINED BsdfEval evalPlastic(vec3 albedo, float roughness, SpecularLayer layer, bool disneyBase, uint flags, vec3 wo,
                           vec3 wi) {
  float side = sideOf(wo);
  vec3 o = mirrorZ(wo, side);
  vec3 i = mirrorZ(wi, side);
  if (o.z < WP_BSDF_MIN_COS || i.z < WP_BSDF_MIN_COS) {
    return noEval();
  }
  float alpha = alphaFromRoughness(roughness);
  float base = disneyBase ? disneyDiffuseFactor(roughness, o.z, i.z, halfVectorOf(o, i).cosine) : 1.0f;
  float diffuse = base * specularLayerTransmission(largestF0(layer), layer.f90, roughness, o.z, i.z) * WP_INV_PI;
  float specularProbability = plasticSpecularProbability(albedo, layer, roughness, o.z, flags);
  BsdfEval e;
  e.fCos = albedo * (diffuse * i.z);
  e.pdf = (1.0f - specularProbability) * cosineHemispherePdf(i.z);
  if (alpha >= WP_DELTA_ALPHA) {
    BsdfEval specular = evalGgxReflection(layer.f0, layer.f90, alpha, o, i);
    e.fCos = e.fCos + specular.fCos;
    e.pdf += specularProbability * specular.pdf;
  }
  return e;
}

// u.x picks the lobe, u.yz the direction.
WP_FN_INLINED MaterialSample samplePlastic(vec3 albedo, float roughness, SpecularLayer layer, bool disneyBase, uint flags,
                                   vec3 wo, vec3 u) {
  float side = sideOf(wo);
  vec3 o = mirrorZ(wo, side);
  if (o.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  float alpha = alphaFromRoughness(roughness);
  float specularProbability = plasticSpecularProbability(albedo, layer, roughness, o.z, flags);
  vec3 wi;
  if (u.x < specularProbability) {
    if (alpha < WP_DELTA_ALPHA) {
      vec3 f = fresnelSchlickTo(layer.f0, layer.f90, o.z) / specularProbability;
      return deltaSample(mirrorDirection(o), f, specularProbability, side);
    }
    wi = sampleGgxReflection(alpha, o, make_vec2(u.y, u.z));
  } else {
    wi = sampleCosineHemisphere(make_vec2(u.y, u.z));
  }
  if (wi.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  return sampleFromEval(wi, evalPlastic(albedo, roughness, layer, disneyBase, flags, o, wi), side);
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
