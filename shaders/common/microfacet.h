// Microfacet normal distributions (GGX and Beckmann), their shadowing-masking terms and the
// sampling of microfacet normals. Normals are in the local frame (z = macro normal).
#ifndef WP_MICROFACET_H
#define WP_MICROFACET_H

#include "portable.h"

WP_BEGIN

// Below this alpha a surface is treated as perfectly smooth: its lobes become delta lobes
// (a mirror direction or Snell's law), because D would exceed float range near alpha = 0
// and the lobe could never be hit by light sampling anyway. alpha = 1e-3 is a perceptual
// roughness of about 0.03.
#define WP_DELTA_ALPHA 1e-3f

// glTF's perceptual roughness r maps to alpha = r^2 (Burley 2012), which spreads the
// visually distinct materials evenly over r.
WP_FN float alphaFromRoughness(float roughness) {
  float r = clamp(roughness, 0.0f, 1.0f);
  return r * r;
}

WP_FN vec3 sphericalDirection(float sinTheta, float cosTheta, float phi) {
  return make_vec3(sinTheta * WP_WARP_COS(phi), sinTheta * WP_WARP_SIN(phi), cosTheta);
}

// ---- GGX (Trowbridge-Reitz), Walter et al. 2007 ----

// D(m) = alpha^2 / (pi (alpha^2 cos^2 + sin^2)^2) for a unit normal m with m.z > 0, else 0.
// sin^2 is taken from m.x and m.y: 1 - cos^2 would cancel catastrophically near the peak,
// where a narrow lobe (alpha^2 ~ 1e-5) needs it most.
WP_FN float ggxD(float alpha, vec3 m) {
  if (m.z <= 0.0f) {
    return 0.0f;
  }
  float a2 = alpha * alpha;
  float d = a2 * m.z * m.z + m.x * m.x + m.y * m.y;
  return a2 / (WP_PI * d * d);
}

// The height-correlated Smith term folded with the BRDF's denominator,
// V = G2 / (4 cosO cosI) (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", listing 2):
// the division by the cosines cancels analytically, so grazing angles cannot blow up.
// Requires cosO, cosI > 0.
WP_FN float ggxVisibility(float alpha, float cosO, float cosI) {
  float a2 = alpha * alpha;
  float lambdaO = cosI * sqrt((cosO - cosO * a2) * cosO + a2);
  float lambdaI = cosO * sqrt((cosI - cosI * a2) * cosI + a2);
  return 0.5f / (lambdaO + lambdaI);
}

// Smith's masking G1 of the GGX distribution for a direction with cos(theta) = cosTheta > 0:
// 1 / (1 + Lambda) = 2 cos / (cos + sqrt(alpha^2 + (1 - alpha^2) cos^2)).
WP_FN float ggxG1(float alpha, float cosTheta) {
  float a2 = alpha * alpha;
  return 2.0f * cosTheta / (cosTheta + sqrt(a2 + (1.0f - a2) * cosTheta * cosTheta));
}

// A microfacet normal visible from `o` (o.z > 0), with density G1(o) max(0, o.m) D(m) / o.z
// over solid angle (Heitz 2018, "Sampling the GGX Distribution of Visible Normals"): the
// hemisphere of a unit-roughness configuration stretched by alpha is sampled by its
// projected area as seen from o. Reflections of o about such normals have weights
// F G2 / G1(o), which stay near F where sampling D(m) cos(theta_m) gives peaks at grazing
// angles.
WP_FN vec3 sampleGgxVisibleNormal(float alpha, vec3 o, vec2 u) {
  vec3 stretched = normalize(make_vec3(alpha * o.x, alpha * o.y, o.z));
  float lengthSquared = stretched.x * stretched.x + stretched.y * stretched.y;
  vec3 t1 = lengthSquared > 0.0f ? make_vec3(-stretched.y, stretched.x, 0.0f) / sqrt(lengthSquared)
                                 : make_vec3(1.0f, 0.0f, 0.0f);
  vec3 t2 = cross(stretched, t1);
  float r = sqrt(u.x);
  float phi = 2.0f * WP_PI * u.y;
  float p1 = r * WP_WARP_COS(phi);
  float s = 0.5f * (1.0f + stretched.z);
  float p2 = (1.0f - s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + s * r * WP_WARP_SIN(phi);
  vec3 n = t1 * p1 + t2 * p2 + stretched * sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2));
  return normalize(make_vec3(alpha * n.x, alpha * n.y, max(0.0f, n.z)));
}

// ---- Beckmann, Walter et al. 2007 ----

// D(m) = exp(-tan^2 / alpha^2) / (pi alpha^2 cos^4) for a unit normal m with m.z > 0,
// else 0 (tan^2 from m.x and m.y, as in ggxD).
WP_FN float beckmannD(float alpha, vec3 m) {
  if (m.z <= 0.0f) {
    return 0.0f;
  }
  float c2 = m.z * m.z;
  float x = (m.x * m.x + m.y * m.y) / (c2 * alpha * alpha);
  // exp(-80) is 2e-35: past it D is 0 in float anyway, and cos^4 could underflow to 0/0.
  if (x > 80.0f) {
    return 0.0f;
  }
  return exp(-x) / (WP_PI * alpha * alpha * c2 * c2);
}

// Smith's monodirectional shadowing G1 for a direction with |cos(theta)| = cosTheta, by
// Walter et al.'s rational approximation of the erf form (their eq. 27; GLSL has no erf).
// The side condition (the direction sees the facet's front) is checked by the callers.
WP_FN float beckmannG1(float alpha, float cosTheta) {
  float sinTheta = sqrt(max(0.0f, 1.0f - cosTheta * cosTheta));
  if (sinTheta <= 0.0f) {
    return 1.0f;
  }
  float a = cosTheta / (alpha * sinTheta);
  if (a >= 1.6f) {
    return 1.0f;
  }
  return (3.535f * a + 2.181f * a * a) / (1.0f + 2.276f * a + 2.577f * a * a);
}

// A microfacet normal with density beckmannD(alpha, m) * m.z over solid angle:
// tan^2(theta) = -alpha^2 ln(1 - u), u in [0, 1).
WP_FN vec3 sampleBeckmannNormal(float alpha, vec2 u) {
  float tan2 = -alpha * alpha * log(1.0f - u.x);
  float cosTheta = 1.0f / sqrt(1.0f + tan2);
  return sphericalDirection(sqrt(tan2) * cosTheta, cosTheta, 2.0f * WP_PI * u.y);
}

// Walter et al. 2007 (section 5.3) sample Beckmann normals from a slightly wider lobe,
// alpha' = (1.2 - 0.2 sqrt(|cos(theta_o)|)) alpha, which keeps sample weights small at
// grazing angles. Depends on the outgoing direction only, so the pdf stays computable.
WP_FN float widenedBeckmannAlpha(float alpha, float cosThetaO) {
  return (1.2f - 0.2f * sqrt(fabs(cosThetaO))) * alpha;
}

WP_END

#endif
