// Single-scattering GGX reflection with a Schlick Fresnel, glTF 2.0's specular_brdf
// (Appendix B) times F, sampled by its visible normals. Metal and plastic build on it, and
// tools/make_bsdf_tables.cpp integrates it for energy_compensation.h.
#ifndef WP_GGX_REFLECTION_H
#define WP_GGX_REFLECTION_H

#include "bsdf_sample.h"
#include "fresnel.h"
#include "microfacet.h"

WP_BEGIN

// f |cos(theta_i)| = F(i.h) D(h) V(o, i) cos(theta_i), with F Schlick's curve from `f0`
// per channel to `f90` (1 but for KHR_materials_specular), and the density of
// sampleGgxReflection: D_o(h) / (4 o.h) = G1(o) D(h) / (4 cos(theta_o)), the visible normal's
// density times the Jacobian of reflection. Both directions must be in the upper hemisphere
// (the callers mirror them there).
WP_FN BsdfEval evalGgxReflection(vec3 f0, float f90, float alpha, vec3 o, vec3 i) {
  if (o.z < WP_BSDF_MIN_COS || i.z < WP_BSDF_MIN_COS) {
    return noEval();
  }
  HalfVector h = halfVectorOf(o, i);
  float d = ggxD(alpha, h.normal);
  BsdfEval e;
  e.fCos = fresnelSchlickTo(f0, f90, h.cosine) * (d * ggxVisibility(alpha, o.z, i.z) * i.z);
  e.pdf = ggxG1(alpha, o.z) * d / (4.0f * o.z);
  return e;
}

// A reflected direction for o in the upper hemisphere with the density of
// evalGgxReflection. It can point below the horizon (a visible facet can still reflect
// downwards); the caller rejects it.
WP_FN vec3 sampleGgxReflection(float alpha, vec3 o, vec2 u) { return reflectAbout(o, sampleGgxVisibleNormal(alpha, o, u)); }

WP_END

#endif
