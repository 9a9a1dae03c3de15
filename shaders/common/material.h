// A glTF metallic-roughness material as one BSDF: its base lobes (metal, glass, plastic)
// mixed stochastically, under a sheen layer (KHR_materials_sheen) and a clear coat
// (KHR_materials_clearcoat); plus Beer's-law absorption and the contribution clamp.
#ifndef WP_MATERIAL_H
#define WP_MATERIAL_H

#include "bsdf_models.h"
#include "sheen.h"

WP_BEGIN

WP_STRUCT(SurfaceMaterial)
  vec3 baseColor;      // metal: F0; plastic: diffuse albedo; glass: transmission tint
  float metallic;      // in [0, 1]: weight of the metal lobe
  float roughness;     // glTF perceptual roughness in [0, 1]; alpha = roughness^2
  float ior;           // n(inside) / n(outside), glTF default 1.5
  float transmission;  // in [0, 1]: weight of glass within the non-metal part
  bool disneyDiffuse;  // plastic's base: the seed report's Disney diffuse instead of Lambert
  // KHR_materials_specular: the dielectric specular layer's weight (F90, and a factor on F0)
  // and the colour F0 is tinted by; 1 and white without the extension.
  float specularWeight;
  vec3 specularColor;
  // KHR_materials_sheen: a layer of microfibers over the base; colour 0: none.
  vec3 sheenColor;
  float sheenRoughness;
  // KHR_materials_clearcoat: a GGX layer of IOR 1.5 over everything; 0: none. Its normal is
  // in the local shading frame (z: the base's normal; (0, 0, 1) without a coat normal map).
  float clearcoat;
  float clearcoatRoughness;
  vec3 clearcoatNormal;
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

// `m` with the extensions' fields at their glTF defaults: full white specular, no sheen, no coat.
WP_FN SurfaceMaterial withDefaultExtensions(SurfaceMaterial m) {
  m.specularWeight = 1.0f;
  m.specularColor = make_vec3(1.0f, 1.0f, 1.0f);
  m.sheenColor = make_vec3(0.0f, 0.0f, 0.0f);
  m.sheenRoughness = 0.0f;
  m.clearcoat = 0.0f;
  m.clearcoatRoughness = 0.0f;
  m.clearcoatNormal = make_vec3(0.0f, 0.0f, 1.0f);
  return m;
}

WP_FN SpecularLayer specularLayerOf(SurfaceMaterial m) {
  return dielectricSpecular(m.ior, m.specularColor, m.specularWeight);
}

// The base's f * |cos(theta_i)| and the density of wi under sampleBaseMaterial.
WP_FN BsdfEval evalBaseMaterial(SurfaceMaterial m, vec3 wo, vec3 wi, uint flags) {
  LobeWeights w = lobeWeightsOf(m);
  float alpha = alphaFromRoughness(m.roughness);
  BsdfEval e = noEval();
  if (WP_SCENE_METALLIC && w.metal > 0.0f) {
    e = addWeighted(e, evalMetal(m.baseColor, m.roughness, wo, wi), w.metal);
  }
  if (WP_SCENE_TRANSMISSIVE && w.glass > 0.0f) {
    e = addWeighted(e, evalGlass(m.baseColor, alpha, m.ior, flags, wo, wi), w.glass);
  }
  if (w.plastic > 0.0f) {
    e = addWeighted(e, evalPlastic(m.baseColor, m.roughness, specularLayerOf(m), m.disneyDiffuse, flags, wo, wi),
                    w.plastic);
  }
  return e;
}

// Reuses the part of a uniform number below `probability`, rescaled to [0, 1), for a
// later choice; kept below 1 against rounding.
WP_FN float rescaleUniform(float u, float probability) { return min(u / probability, 0.99999994f); }

// u in [0, 1)^3: u.x picks the base lobe (and, rescaled, the lobe's own reflect/refract or
// specular/diffuse choice), u.yz the direction. A delta sample carries WP_SAMPLE_DELTA and
// its pdf is the probability of the delta lobe.
WP_FN_INLINED MaterialSample sampleBaseMaterial(SurfaceMaterial m, vec3 wo, vec3 u, uint flags) {
  LobeWeights w = lobeWeightsOf(m);
  float alpha = alphaFromRoughness(m.roughness);
  MaterialSample s;
  float chosen;
  // (WP_SCENE_METALLIC false: no material has metalness, w.metal is 0 and this never runs,
  // and Vulkan and OpenCL compile the metal lobe away.)
  if (WP_SCENE_METALLIC && u.x < w.metal) {
    chosen = w.metal;
    s = sampleMetal(m.baseColor, m.roughness, wo, make_vec3(rescaleUniform(u.x, w.metal), u.y, u.z));
  } else {
    // u.x >= metallic and x < 1, so each division below is by a positive number.
    float x = rescaleUniform(u.x - w.metal, 1.0f - w.metal);
    float transmission = clamp(m.transmission, 0.0f, 1.0f);
    if (WP_SCENE_TRANSMISSIVE && x < transmission) {
      chosen = w.glass;
      s = sampleGlass(m.baseColor, alpha, m.ior, flags, wo, make_vec3(rescaleUniform(x, transmission), u.y, u.z));
    } else {
      chosen = w.plastic;
      s = samplePlastic(m.baseColor, m.roughness, specularLayerOf(m), m.disneyDiffuse, flags, wo,
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
  BsdfEval e = evalBaseMaterial(m, wo, s.wi, flags);
  if (!(e.pdf > 0.0f)) {
    return noSample();
  }
  s.weight = e.fCos / e.pdf;
  s.pdf = e.pdf;
  return s;
}

// ---- The layers over the base: sheen, then the clear coat ----------------------------
//
// f = f_coat + s_coat (f_sheen + s_sheen f_base), the order glTF gives (the coat over the
// sheen over the base). Each layer lets through to what lies below the energy it does not
// reflect, by Kulla & Conty's albedo scaling in the reciprocal form the sheen extension
// suggests, s = min(1 - w E(o), 1 - w E(i)), E the layer's directional albedo (a table) and w
// its strength: with the base reflecting at most 1, the whole reflects at most 1. The coat is
// GGX of IOR 1.5 (F0 0.04) with its own roughness and normal; the sheen, Charlie's lobe.
// Directions are mirrored into wo's hemisphere, as the opaque lobes are.

// (WP_SCENE_LAYERED false: the scene has none, and Vulkan and OpenCL compile the layers away.)
WP_FN bool hasLayers(SurfaceMaterial m) {
  return WP_SCENE_LAYERED && (m.clearcoat > 0.0f || max(m.sheenColor.x, max(m.sheenColor.y, m.sheenColor.z)) > 0.0f);
}

#define WP_COAT_F0 0.04f

WP_FN bool coatIsDelta(SurfaceMaterial m) { return alphaFromRoughness(m.clearcoatRoughness) < WP_DELTA_ALPHA; }

// The coat's strength times its directional albedo at cos(theta) about its own normal.
WP_FN float coatAlbedo(SurfaceMaterial m, float cosTheta) {
  return clamp(m.clearcoat, 0.0f, 1.0f) * ggxSpecularAlbedo(WP_COAT_F0, 1.0f, m.clearcoatRoughness, cosTheta);
}

// The sheen's strength (its colour's largest channel) times its directional albedo.
WP_FN float sheenAlbedo(SurfaceMaterial m, float cosTheta) {
  float strength = max(m.sheenColor.x, max(m.sheenColor.y, m.sheenColor.z));
  return strength > 0.0f ? strength * bsdfTableAt(WP_TABLE_SHEEN, m.sheenRoughness, cosTheta) : 0.0f;
}

// The layers at one pair of directions, in wo's mirrored hemisphere: o and i in the base's
// frame, and about the coat's normal.
WP_STRUCT(LayerFrame)
  vec3 o;
  vec3 i;
  Frame coatFrame;
  vec3 coatO;  // o about the coat's normal
  vec3 coatI;
WP_STRUCT_END(LayerFrame)

WP_FN LayerFrame layerFrameOf(SurfaceMaterial m, vec3 wo, vec3 wi) {
  float side = sideOf(wo);
  LayerFrame f;
  f.o = mirrorZ(wo, side);
  f.i = mirrorZ(wi, side);
  // Seen from the back, the coat's normal turns with the surface's: -n mirrored.
  vec3 coatNormal = side > 0.0f ? m.clearcoatNormal : make_vec3(-m.clearcoatNormal.x, -m.clearcoatNormal.y, m.clearcoatNormal.z);
  f.coatFrame = makeFrame(normalize(coatNormal));
  f.coatO = frameToLocal(f.coatFrame, f.o);
  f.coatI = frameToLocal(f.coatFrame, f.i);
  return f;
}

// Which layer a sample comes from: the coat with the energy it reflects, the sheen with what
// it reflects of the rest, the base with the remainder (the three sum to 1).
WP_STRUCT(LayerChoice)
  float coat;
  float sheen;
  float base;
WP_STRUCT_END(LayerChoice)

WP_FN LayerChoice layerChoiceOf(SurfaceMaterial m, LayerFrame f) {
  float coat = coatAlbedo(m, f.coatO.z);
  float sheen = sheenAlbedo(m, f.o.z);
  LayerChoice c;
  c.coat = coat;
  c.sheen = (1.0f - coat) * sheen;
  c.base = (1.0f - coat) * (1.0f - sheen);
  return c;
}

// What the layers above let through to the base for the pair: s_coat s_sheen. A transmitted
// direction passes the layers at its own |cos|.
WP_FN float baseScale(SurfaceMaterial m, LayerFrame f) {
  float coat = min(1.0f - coatAlbedo(m, f.coatO.z), 1.0f - coatAlbedo(m, fabs(f.coatI.z)));
  float sheen = min(1.0f - sheenAlbedo(m, f.o.z), 1.0f - sheenAlbedo(m, fabs(f.i.z)));
  return coat * sheen;
}

WP_FN float sheenScale(SurfaceMaterial m, LayerFrame f) {
  return min(1.0f - coatAlbedo(m, f.coatO.z), 1.0f - coatAlbedo(m, fabs(f.coatI.z)));
}

// f * |cos(theta_i)| and the density of wi under sampleMaterial, computed together.
// `flags`: WP_BSDF_* switches, the same as given to sampleMaterial. Each layer's cosine is
// taken about its own normal.
WP_FN BsdfEval evalMaterial(SurfaceMaterial m, vec3 wo, vec3 wi, uint flags) {
  BsdfEval base = evalBaseMaterial(m, wo, wi, flags);
  if (!hasLayers(m)) {
    return base;
  }
  LayerFrame f = layerFrameOf(m, wo, wi);
  LayerChoice choice = layerChoiceOf(m, f);
  BsdfEval e;
  e.fCos = base.fCos * baseScale(m, f);
  e.pdf = choice.base * base.pdf;
  if (choice.sheen > 0.0f) {
    BsdfEval sheen = evalSheen(m.sheenColor, m.sheenRoughness, f.o, f.i);
    e.fCos = e.fCos + sheen.fCos * sheenScale(m, f);
    e.pdf += choice.sheen * sheen.pdf;
  }
  if (choice.coat > 0.0f && !coatIsDelta(m)) {
    float coat = clamp(m.clearcoat, 0.0f, 1.0f);
    BsdfEval layer = evalGgxReflection(make_vec3(WP_COAT_F0, WP_COAT_F0, WP_COAT_F0), 1.0f,
                                       alphaFromRoughness(m.clearcoatRoughness), f.coatO, f.coatI);
    e.fCos = e.fCos + layer.fCos * coat;
    e.pdf += choice.coat * layer.pdf;
  }
  return e;
}

WP_FN float pdfMaterial(SurfaceMaterial m, vec3 wo, vec3 wi, uint flags) {
  return evalMaterial(m, wo, wi, flags).pdf;
}

// u in [0, 1)^3: u.x picks the layer (and, rescaled, the base's lobe and that lobe's own
// choice), u.yz the direction. A delta sample carries WP_SAMPLE_DELTA and its pdf is the
// probability of the delta lobe; the caller must then skip MIS.
WP_FN MaterialSample sampleMaterial(SurfaceMaterial m, vec3 wo, vec3 u, uint flags) {
  if (!hasLayers(m)) {
    return sampleBaseMaterial(m, wo, u, flags);
  }
  float side = sideOf(wo);
  LayerFrame f = layerFrameOf(m, wo, wo);
  if (f.o.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  LayerChoice choice = layerChoiceOf(m, f);
  vec3 wi;
  if (u.x < choice.base) {
    MaterialSample s = sampleBaseMaterial(m, wo, make_vec3(rescaleUniform(u.x, choice.base), u.y, u.z), flags);
    if (!(s.pdf > 0.0f)) {
      return noSample();
    }
    if ((s.flags & WP_SAMPLE_DELTA) != 0u) {
      // A delta lobe of the base: only it has this direction; the layers above scale it.
      s.weight = s.weight * (baseScale(m, layerFrameOf(m, wo, s.wi)) / choice.base);
      s.pdf *= choice.base;
      return s;
    }
    wi = s.wi;
  } else if (u.x < choice.base + choice.sheen) {
    wi = mirrorZ(sampleSheen(make_vec2(u.y, u.z)), side);
  } else if (coatIsDelta(m)) {
    // The coat's mirror direction, in wo's mirrored hemisphere (deltaSample turns it back).
    vec3 reflected = frameToWorld(f.coatFrame, mirrorDirection(f.coatO));
    if (reflected.z < WP_BSDF_MIN_COS) {
      return noSample();
    }
    float weight = clamp(m.clearcoat, 0.0f, 1.0f) * fresnelSchlickScalar(WP_COAT_F0, f.coatO.z) / choice.coat;
    return deltaSample(reflected, make_vec3(weight, weight, weight), choice.coat, side);
  } else {
    vec3 coatI = sampleGgxReflection(alphaFromRoughness(m.clearcoatRoughness), f.coatO, make_vec2(u.y, u.z));
    wi = mirrorZ(frameToWorld(f.coatFrame, coatI), side);
  }
  BsdfEval e = evalMaterial(m, wo, wi, flags);
  if (!(e.pdf > 0.0f) || fabs(wi.z) < WP_BSDF_MIN_COS) {
    return noSample();
  }
  MaterialSample s;
  s.wi = wi;
  s.weight = e.fCos / e.pdf;
  s.pdf = e.pdf;
  s.flags = wi.z * wo.z < 0.0f ? WP_SAMPLE_TRANSMISSION : 0u;
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
