// A glTF metallic-roughness material (with KHR_materials_transmission and _ior) as one BSDF:
// its lobes mixed stochastically; plus Beer's-law absorption and the contribution clamp.
#ifndef WP_MATERIAL_H
#define WP_MATERIAL_H

#include "bsdf_models.h"

WP_BEGIN

WP_STRUCT(SurfaceMaterial)
  vec3 baseColor;      // metal: F0; plastic: diffuse albedo; glass: transmission tint
  float metallic;      // in [0, 1]: weight of the metal lobe
  float roughness;     // glTF perceptual roughness in [0, 1]; alpha = roughness^2
  float ior;           // n(inside) / n(outside), glTF default 1.5
  float transmission;  // in [0, 1]: weight of glass within the non-metal part
  bool disneyDiffuse;  // plastic's base: the seed report's Disney diffuse instead of Lambert
WP_STRUCT_END(SurfaceMaterial)

// The mixture f = metallic f_metal + (1 - metallic) (transmission f_glass +
// (1 - transmission) f_plastic), sampled by picking one lobe with probability equal to its
// weight. Its density is the same mixture of the lobes' densities, so a sample's weight is
// f_mixture |cos| / pdf_mixture whichever lobe produced it, and the light-sampling side
// gets the same pdf from pdfMaterial for MIS (one-sample MIS over the lobes).
WP_STRUCT(LobeWeights)
  float metal;
  float glass;
  float plastic;
WP_STRUCT_END(LobeWeights)

WP_FN LobeWeights lobeWeightsOf(SurfaceMaterial m) {
  float metallic = clamp(m.metallic, 0.0f, 1.0f);
  float transmission = clamp(m.transmission, 0.0f, 1.0f);
  LobeWeights w;
  w.metal = metallic;
  w.glass = (1.0f - metallic) * transmission;
  w.plastic = (1.0f - metallic) * (1.0f - transmission);
  return w;
}

// Whether every lobe the material has is a delta lobe (a smooth mirror, smooth glass or a
// mix of the two): what it shows is another surface's, which is where the feature passes
// look (integrator.h).
WP_FN bool materialIsPerfectlySpecular(SurfaceMaterial m) {
  LobeWeights w = lobeWeightsOf(m);
  float alpha = alphaFromRoughness(m.roughness);
  return w.plastic <= 0.0f && (w.metal <= 0.0f || alpha < WP_DELTA_ALPHA) &&
         (w.glass <= 0.0f || glassIsDelta(alpha, m.ior));
}

WP_FN BsdfEval addWeighted(BsdfEval sum, BsdfEval e, float weight) {
  sum.fCos = sum.fCos + e.fCos * weight;
  sum.pdf += e.pdf * weight;
  return sum;
}

// f * |cos(theta_i)| and the density of wi under sampleMaterial, computed together.
// `flags`: WP_BSDF_* switches, the same as given to sampleMaterial.
WP_FN BsdfEval evalMaterial(SurfaceMaterial m, vec3 wo, vec3 wi, uint flags) {
  LobeWeights w = lobeWeightsOf(m);
  float alpha = alphaFromRoughness(m.roughness);
  BsdfEval e = noEval();
  if (w.metal > 0.0f) {
    e = addWeighted(e, evalMetal(m.baseColor, m.roughness, wo, wi), w.metal);
  }
  if (w.glass > 0.0f) {
    e = addWeighted(e, evalGlass(m.baseColor, alpha, m.ior, flags, wo, wi), w.glass);
  }
  if (w.plastic > 0.0f) {
    e = addWeighted(e, evalPlastic(m.baseColor, m.roughness, m.ior, m.disneyDiffuse, flags, wo, wi), w.plastic);
  }
  return e;
}

WP_FN float pdfMaterial(SurfaceMaterial m, vec3 wo, vec3 wi, uint flags) {
  return evalMaterial(m, wo, wi, flags).pdf;
}

// Reuses the part of a uniform number below `probability`, rescaled to [0, 1), for a
// later choice; kept below 1 against rounding.
WP_FN float rescaleUniform(float u, float probability) { return min(u / probability, 0.99999994f); }

// u in [0, 1)^3: u.x picks the lobe (and, rescaled, the lobe's own reflect/refract or
// specular/diffuse choice), u.yz the direction. A delta sample carries WP_SAMPLE_DELTA and
// its pdf is the probability of the delta lobe; the caller must then skip MIS.
WP_FN MaterialSample sampleMaterial(SurfaceMaterial m, vec3 wo, vec3 u, uint flags) {
  LobeWeights w = lobeWeightsOf(m);
  float alpha = alphaFromRoughness(m.roughness);
  MaterialSample s;
  float chosen;
  if (u.x < w.metal) {
    chosen = w.metal;
    s = sampleMetal(m.baseColor, m.roughness, wo, make_vec3(rescaleUniform(u.x, w.metal), u.y, u.z));
  } else {
    // u.x >= metallic and x < 1, so each division below is by a positive number.
    float x = rescaleUniform(u.x - w.metal, 1.0f - w.metal);
    float transmission = clamp(m.transmission, 0.0f, 1.0f);
    if (x < transmission) {
      chosen = w.glass;
      s = sampleGlass(m.baseColor, alpha, m.ior, flags, wo, make_vec3(rescaleUniform(x, transmission), u.y, u.z));
    } else {
      chosen = w.plastic;
      s = samplePlastic(m.baseColor, m.roughness, m.ior, m.disneyDiffuse, flags, wo,
                        make_vec3(rescaleUniform(x - transmission, 1.0f - transmission), u.y, u.z));
    }
  }
  if (!(s.pdf > 0.0f) || chosen >= 1.0f) {
    return s;
  }
  if ((s.flags & WP_SAMPLE_DELTA) != 0u) {
    // Only the chosen lobe has this direction; its weight in the mixture cancels its
    // selection probability.
    s.pdf *= chosen;
    return s;
  }
  BsdfEval e = evalMaterial(m, wo, s.wi, flags);
  if (!(e.pdf > 0.0f)) {
    return noSample();
  }
  s.weight = e.fCos / e.pdf;
  s.pdf = e.pdf;
  return s;
}

// ---- Along the path ------------------------------------------------------------------

WP_FN float beerComponent(float color, float ratio) {
  return color > 0.0f ? exp(log(color) * ratio) : 0.0f;
}

// Transmittance over `distance` inside a medium with glTF KHR_materials_volume's
// attenuation: sigma = -ln(attenuationColor) / attenuationDistance, T = exp(-sigma d),
// i.e. attenuationColor^(d / attenuationDistance). attenuationColor in [0, 1];
// attenuationDistance > 0, infinite (or >= WP_FLT_MAX, glTF's default) for no absorption.
WP_FN vec3 beerLawTransmittance(vec3 attenuationColor, float attenuationDistance, float distance) {
  if (attenuationDistance >= WP_FLT_MAX || distance <= 0.0f) {
    return make_vec3(1.0f, 1.0f, 1.0f);
  }
  float ratio = distance / attenuationDistance;
  return make_vec3(beerComponent(attenuationColor.x, ratio), beerComponent(attenuationColor.y, ratio),
                   beerComponent(attenuationColor.z, ratio));
}

// Biased switch (the seed report's section 4.7): scales a path contribution down to at most
// `maxLuminance`, keeping its hue. Removes fireflies at the price of energy; callers apply
// it only when the render setting asks for it.
WP_FN vec3 clampContribution(vec3 c, float maxLuminance) {
  float l = luminance(c);
  return l > maxLuminance ? c * (maxLuminance / l) : c;
}

WP_END

#endif
