// Fresnel reflectance (Schlick's approximation and the exact dielectric formula) and the
// laws of reflection and refraction about a (micro)facet normal.
#ifndef WP_FRESNEL_H
#define WP_FRESNEL_H

#include "portable.h"

WP_BEGIN

// Schlick 1994: F0 + (1 - F0)(1 - cos)^5, with cosTheta the cosine between the light and
// the (micro)facet normal, clamped to [0, 1]. Metals pass their coloured F0.
WP_FN float schlickWeight(float cosTheta) {
  float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
  float m2 = m * m;
  return m2 * m2 * m;
}

WP_FN vec3 fresnelSchlick(vec3 f0, float cosTheta) {
  return f0 + (make_vec3(1.0f, 1.0f, 1.0f) - f0) * schlickWeight(cosTheta);
}

// Schlick's curve from F0 at normal incidence to F90 at grazing (KHR_materials_specular's
// weight scales both: F90 = specular).
WP_FN vec3 fresnelSchlickTo(vec3 f0, float f90, float cosTheta) {
  return f0 + (make_vec3(f90, f90, f90) - f0) * schlickWeight(cosTheta);
}

WP_FN float fresnelSchlickScalar(float f0, float cosTheta) { return f0 + (1.0f - f0) * schlickWeight(cosTheta); }

// Reflectance at normal incidence of an interface between indices whose ratio is `eta`:
// ((eta - 1) / (eta + 1))^2 (the same for eta and 1 / eta).
WP_FN float f0FromIor(float eta) {
  float r = (eta - 1.0f) / (eta + 1.0f);
  return r * r;
}

// The cosine-weighted hemispherical mean of Schlick's curve,
// 2 * integral of F(mu) mu dmu = F0 + (1 - F0) / 21 (2 * B(2, 6) = 1 / 21).
WP_FN vec3 fresnelSchlickAverage(vec3 f0) { return f0 + (make_vec3(1.0f, 1.0f, 1.0f) - f0) * (1.0f / 21.0f); }

// Exact unpolarized Fresnel reflectance of a dielectric interface (mean of the s and p
// reflectances). cosThetaI in [0, 1] is the cosine on the side the light arrives from and
// eta = n(other side) / n(that side). Returns 1 under total internal reflection.
WP_FN float fresnelDielectric(float cosThetaI, float eta) {
  float cosI = clamp(cosThetaI, 0.0f, 1.0f);
  float sin2T = (1.0f - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0f) {
    return 1.0f;
  }
  float cosT = sqrt(1.0f - sin2T);
  float parallel = (eta * cosI - cosT) / (eta * cosI + cosT);
  float perpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
  return 0.5f * (parallel * parallel + perpendicular * perpendicular);
}

// The mirror image of `w` about the unit normal `m` (both pointing away from the surface).
WP_FN vec3 reflectAbout(vec3 w, vec3 m) { return m * (2.0f * dot(w, m)) - w; }

WP_STRUCT(Refraction)
  vec3 direction;  // the transmitted direction, on the far side of m
  bool valid;      // false under total internal reflection
WP_STRUCT_END(Refraction)

// Snell's law: the direction transmitted through a facet with unit normal `m` for light
// leaving along `w` (dot(w, m) > 0, on the side of m), eta = n(far side) / n(w's side).
WP_FN Refraction refractAbout(vec3 w, vec3 m, float eta) {
  Refraction r;
  float cosI = dot(w, m);
  float sin2T = (1.0f - cosI * cosI) / (eta * eta);
  r.valid = sin2T < 1.0f;
  float cosT = sqrt(max(0.0f, 1.0f - sin2T));
  r.direction = m * (cosI / eta - cosT) - w / eta;
  return r;
}

WP_END

#endif
