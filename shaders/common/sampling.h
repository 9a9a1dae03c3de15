// Sampling routines and their densities: orthonormal frames, cosine hemisphere, triangles.
#ifndef WP_SAMPLING_H
#define WP_SAMPLING_H

#include "portable.h"

WP_BEGIN

WP_STRUCT(Frame)
  vec3 tangent;
  vec3 bitangent;
  vec3 normal;
WP_STRUCT_END(Frame)

// Orthonormal basis around a unit normal (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited"), with the side s of its one discontinuity moved off n.z = 0. Every frame field
// over the sphere jumps somewhere (the hairy ball theorem); Duff et al. put the jump at
// n.z = 0, where every wall and floor parallel to the z axis lies, and where a normal whose
// n.z is zero only in exact arithmetic comes out +-1e-10 or so: NVIDIA fuses the cross
// product of a triangle's edges into fmas, lavapipe and PoCL do not, so the two picked
// opposite frames on a wall of the Cornell box, and sent the same random numbers in other
// directions there (the images agreed in the mean, not sample for sample). At n.z = -0.6 lie
// no faces of round angles (0, 30, 45, 60, 90 degrees); 1 + n.z stays at least 0.4, so the
// frame keeps its precision.
WP_FN Frame makeFrame(vec3 n) {
  float s = n.z >= -0.6f ? 1.0f : -1.0f;
  float a = -1.0f / (s + n.z);
  float b = n.x * n.y * a;
  Frame f;
  f.tangent = make_vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
  f.bitangent = make_vec3(b, s + n.y * n.y * a, -n.y);
  f.normal = n;
  return f;
}

WP_FN vec3 frameToWorld(Frame f, vec3 v) { return f.tangent * v.x + f.bitangent * v.y + f.normal * v.z; }

WP_FN vec3 frameToLocal(Frame f, vec3 v) {
  return make_vec3(dot(v, f.tangent), dot(v, f.bitangent), dot(v, f.normal));
}

// A point uniform over the unit disk by Shirley & Chiu's concentric map (1997, "A low
// distortion map between disk and square"), which keeps strata of u compact on the lens.
WP_FN vec2 sampleConcentricDisk(vec2 u) {
  float ox = 2.0f * u.x - 1.0f;
  float oy = 2.0f * u.y - 1.0f;
  if (ox == 0.0f && oy == 0.0f) return make_vec2(0.0f, 0.0f);
  float r;
  float phi;
  if (fabs(ox) > fabs(oy)) {
    r = ox;
    phi = (WP_PI * 0.25f) * (oy / ox);
  } else {
    r = oy;
    phi = (WP_PI * 0.5f) - (WP_PI * 0.25f) * (ox / oy);
  }
  return make_vec2(r * WP_WARP_COS(phi), r * WP_WARP_SIN(phi));
}

// Cosine-weighted direction on the +z hemisphere (Malley's method: a uniform disk point
// lifted to the hemisphere). Density: cosineHemispherePdf(z).
WP_FN vec3 sampleCosineHemisphere(vec2 u) {
  vec2 d = sampleConcentricDisk(u);
  return make_vec3(d.x, d.y, sqrt(max(0.0f, 1.0f - d.x * d.x - d.y * d.y)));
}

// Solid-angle density of sampleCosineHemisphere for a direction with cos(theta) = cosTheta.
WP_FN float cosineHemispherePdf(float cosTheta) { return max(cosTheta, 0.0f) * WP_INV_PI; }

// Barycentrics (b1, b2) of a point uniform over a triangle's area (the square-root warp,
// Shirley & Chiu); the point is v0 + b1 * edge1 + b2 * edge2.
WP_FN vec2 sampleUniformTriangle(vec2 u) {
  float su = sqrt(u.x);
  return make_vec2(1.0f - su, u.y * su);
}

// Converts a density over area at a point seen at `distanceSquared` under cos(theta) =
// cosAtSurface into a density over solid angle at the viewer; 0 when seen edge-on.
WP_FN float areaToSolidAnglePdf(float areaPdf, float distanceSquared, float cosAtSurface) {
  float c = fabs(cosAtSurface);
  return c > 0.0f ? areaPdf * distanceSquared / c : 0.0f;
}

// Balance heuristic weight of a strategy with density `pdf` against one with `otherPdf`
// (one sample each, Veach 1997).
WP_FN float balanceHeuristic(float pdf, float otherPdf) {
  float sum = pdf + otherPdf;
  return sum > 0.0f ? pdf / sum : 0.0f;
}

WP_FN float luminance(vec3 c) { return dot(c, make_vec3(0.2126f, 0.7152f, 0.0722f)); }

WP_FN float maxComponent(vec3 c) { return max(c.x, max(c.y, c.z)); }

WP_END

#endif
