// The BSDF of a GpuMaterial: ideal diffuse (Lambert), or the glTF metallic-roughness mixture
// of material.h. Directions are in the local frame whose z is the surface's outward normal
// (not flipped towards wo: glass needs to know which side the path is on).
#ifndef WP_BSDF_H
#define WP_BSDF_H

#include "layout.h"
#include "material.h"

WP_BEGIN

WP_FN vec3 albedoOf(GpuMaterial m) { return make_vec3(m.baseColor.x, m.baseColor.y, m.baseColor.z); }

WP_FN SurfaceMaterial surfaceMaterialOf(GpuMaterial m) {
  SurfaceMaterial s;
  s.baseColor = albedoOf(m);
  s.metallic = m.surface.x;
  s.roughness = m.surface.y;
  s.ior = m.surface.z;
  s.transmission = materialTransmission(m);
  s.disneyDiffuse = materialKind(m) == WP_MATERIAL_GLTF_DISNEY_DIFFUSE;
  s.specularWeight = materialSpecularWeight(m);
  s.specularColor = materialSpecularColor(m);
  s.sheenColor = materialSheenColor(m);
  s.sheenRoughness = materialSheenRoughness(m);
  s.clearcoat = materialClearcoat(m);
  s.clearcoatRoughness = materialClearcoatRoughness(m);
  s.clearcoatNormal = materialClearcoatNormal(m);
  return s;
}

// `m` with every microfacet lobe (the base's metal, specular layer and glass, and the clear
// coat) at least `floorRoughness` rough (perceptual): filter glossy (glossyFloorRoughness,
// integrator.h). Sheen and the diffuse base are not microfacet lobes and keep theirs, as in
// Cycles, but the seed's Disney diffuse (WP_MATERIAL_GLTF_DISNEY_DIFFUSE) shares the base's
// roughness and follows it.
WP_FN GpuMaterial withGlossyFloor(GpuMaterial m, float floorRoughness) {
  m.surface.y = max(m.surface.y, floorRoughness);
  m.clearcoat.y = max(m.clearcoat.y, floorRoughness);
  return m;
}

// Lambert, two-sided: albedo / pi into wo's hemisphere, sampled by the cosine.
WP_FN BsdfEval evalLambert(vec3 albedo, vec3 wo, vec3 wi) {
  float side = sideOf(wo);
  float cosI = wi.z * side;
  if (wo.z * side < WP_BSDF_MIN_COS || cosI < WP_BSDF_MIN_COS) {
    return noEval();
  }
  BsdfEval e;
  e.fCos = albedo * (cosI * WP_INV_PI);
  e.pdf = cosineHemispherePdf(cosI);
  return e;
}

WP_FN_INLINED MaterialSample sampleLambert(vec3 albedo, vec3 wo, vec2 u) {
  float side = sideOf(wo);
  vec3 wi = sampleCosineHemisphere(u);
  if (wo.z * side < WP_BSDF_MIN_COS || wi.z < WP_BSDF_MIN_COS) {
    return noSample();
  }
  return sampleFromEval(wi, evalLambert(albedo, mirrorZ(wo, side), wi), side);
}

// f |cos(theta_i)| and the density of wi under sampleBsdf with the same `flags` (WP_BSDF_*).
// An unlit material scatters nothing (its colour is emission, integrator.h).
WP_FN BsdfEval evalBsdf(GpuMaterial m, vec3 wo, vec3 wi, uint flags) {
  if (materialKind(m) == WP_MATERIAL_UNLIT) {
    return noEval();
  }
  if (!WP_SCENE_MICROFACET || materialKind(m) == WP_MATERIAL_LAMBERT) {  // (see prelude_glsl.h)
    return evalLambert(albedoOf(m), wo, wi);
  }
  return evalMaterial(surfaceMaterialOf(m), wo, wi, flags);
}

// Whether the material reflects and transmits only in delta directions (materialIsPerfectlySpecular).
WP_FN bool bsdfIsPerfectlySpecular(GpuMaterial m) {
  return WP_SCENE_MICROFACET && materialKind(m) != WP_MATERIAL_LAMBERT && materialIsPerfectlySpecular(surfaceMaterialOf(m));
}

// u in [0, 1)^3; see sampleMaterial for delta samples.
WP_FN_INLINED MaterialSample sampleBsdf(GpuMaterial m, vec3 wo, vec3 u, uint flags) {
  if (materialKind(m) == WP_MATERIAL_UNLIT) {
    return noSample();
  }
  if (!WP_SCENE_MICROFACET || materialKind(m) == WP_MATERIAL_LAMBERT) {  // (see prelude_glsl.h)
    return sampleLambert(albedoOf(m), wo, make_vec2(u.y, u.z));
  }
  return sampleMaterial(surfaceMaterialOf(m), wo, u, flags);
}

WP_END

#endif
