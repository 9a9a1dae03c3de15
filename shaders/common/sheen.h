// KHR_materials_sheen's sheen lobe: the "Charlie" microfiber distribution and visibility of
// Estevez & Kulla 2017 ("Production Friendly Microfacet Sheen BRDF"), as the extension writes
// them, with F = 1. It reflects back towards grazing angles, the look of velvet.
#ifndef WP_SHEEN_H
#define WP_SHEEN_H

#include "bsdf_sample.h"
#include "sampling.h"

WP_BEGIN

// The extension takes alpha = sheenRoughness itself. Below this the distribution's exponent
// 1 / alpha overflows float (and the lobe is a thin rim no sample finds), so it is clamped,
// as real-time implementations clamp it too.
#define WP_SHEEN_MIN_ALPHA 0.07f

WP_FN float sheenAlpha(float roughness) { return clamp(roughness, WP_SHEEN_MIN_ALPHA, 1.0f); }

// D(h) = (2 + 1 / alpha) sin(theta_h)^(1 / alpha) / (2 pi). sin^2 from h.x and h.y, as ggxD
// takes it, so that it stays exact near the normal.
WP_FN float charlieD(float alpha, vec3 h) {
  float sin2 = max(h.x * h.x + h.y * h.y, 1e-12f);
  float inverse = 1.0f / alpha;
  return (2.0f + inverse) * WP_BSDF_POW(sin2, 0.5f * inverse) / (2.0f * WP_PI);
}

// The fitted exponent of Charlie's Lambda (the extension's l(x, alpha)).
WP_FN float charlieL(float x, float alpha) {
  float t = (1.0f - alpha) * (1.0f - alpha);
  float a = mix(21.5473f, 25.3245f, t);
  float b = mix(3.82987f, 3.32435f, t);
  float c = mix(0.19823f, 0.16801f, t);
  float d = mix(-1.97760f, -1.27393f, t);
  float e = mix(-4.32054f, -4.85967f, t);
  return a / (1.0f + b * WP_BSDF_POW(x, c)) + d * x + e;
}

WP_FN float charlieLambda(float alpha, float cosTheta) {
  return cosTheta < 0.5f ? exp(charlieL(cosTheta, alpha)) : exp(2.0f * charlieL(0.5f, alpha) - charlieL(1.0f - cosTheta, alpha));
}

// V = G2 / (4 cos_o cos_i) with the height-correlated G2 = 1 / (1 + Lambda(o) + Lambda(i)).
WP_FN float charlieVisibility(float alpha, float cosO, float cosI) {
  return 1.0f / ((1.0f + charlieLambda(alpha, cosO) + charlieLambda(alpha, cosI)) * (4.0f * cosO * cosI));
}

// f |cos(theta_i)| = colour D V cos(theta_i) for o and i in the upper hemisphere, and the
// density of sampleSheen: the cosine (the lobe is broad, its weight bounded).
WP_FN BsdfEval evalSheen(vec3 color, float roughness, vec3 o, vec3 i) {
  if (o.z < WP_BSDF_MIN_COS || i.z < WP_BSDF_MIN_COS) {
    return noEval();
  }
  float alpha = sheenAlpha(roughness);
  vec3 h = normalize(o + i);
  BsdfEval e;
  e.fCos = color * (charlieD(alpha, h) * charlieVisibility(alpha, o.z, i.z) * i.z);
  e.pdf = cosineHemispherePdf(i.z);
  return e;
}

WP_FN vec3 sampleSheen(vec2 u) { return sampleCosineHemisphere(u); }

WP_END

#endif
