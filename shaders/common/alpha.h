// Alpha coverage (glTF alphaMode), tested on every hit of an alpha-tested triangle
// (traceCovered in traverse.h), so camera, extension and shadow rays all see it: MASK cuts a
// surface out where its alpha is below alphaCutoff; BLEND is stochastic transparency, a ray
// passing a surface with probability 1 - alpha.
#ifndef WP_ALPHA_H
#define WP_ALPHA_H

#include "binding_table.h"
#include "rng.h"
#include "surface.h"
#include "texture.h"

WP_BEGIN

// The seed of a ray's BLEND decisions: a hash of its origin and direction, which every ray
// has, so extension and shadow rays decide alike without carrying a random number, and a
// render stays deterministic for its seed.
WP_FN uint coverageSeedOf(vec3 origin, vec3 direction) {
  uint h = pcgHash(asUint(origin.x));
  h = pcgHash(h ^ asUint(origin.y));
  h = pcgHash(h ^ asUint(origin.z));
  h = pcgHash(h ^ asUint(direction.x));
  h = pcgHash(h ^ asUint(direction.y));
  return pcgHash(h ^ asUint(direction.z));
}

// The uniform number in [0, 1) that decides whether the ray of `seed` passes triangle
// `primitive` of instance `instance`. Each (ray, triangle, instance) gets its own, so the
// decisions at the surfaces along a ray are independent (an instanced leaf seen twice
// included): the nearest surface that stops the ray is found with the probability
// stochastic transparency asks for.
WP_FN float coverageUniform(uint seed, uint instance, uint primitive) {
  return rngFloat(pcgHash(seed ^ pcgHash(primitive ^ pcgHash(instance ^ 0x2545f491u))));
}

// The base colour's alpha at barycentrics b of triangle `primitive` (glTF: baseColorFactor's
// alpha times COLOR_0's times the base colour texture's), as the shade stage's
// texturedMaterial would compute it.
WP_FN float coverageAlpha(WP_BUFFERS GpuMaterial m, uint primitive, vec2 b) {
  GpuTriangleShading shading = WP_LOAD(triangleShading, primitive);
  float alpha = m.baseColor.w * colorAt(shading, b).w;
  TexCoords c = texCoordsAt(shading, b);
  if (textureApplies(WP_BUFFERS_ARG materialBaseColorTexture(m), c)) {
    alpha *= sampleTexture(WP_BUFFERS_ARG materialBaseColorTexture(m), c).w;
  }
  return alpha;
}

// Whether triangle `tri` (global index `primitive`, of `instance`) stops the ray of `seed`
// at the object-space point p. Only called for triangles with triangleAlphaTested.
WP_FN bool triangleCovers(WP_BUFFERS GpuTriangle tri, uint primitive, uint instance, vec3 p, uint seed) {
  GpuMaterial m = WP_LOAD(materials, triangleMaterial(tri));
  float alpha = coverageAlpha(WP_BUFFERS_ARG m, primitive, barycentricsAt(tri, p));
  if (materialAlphaMode(m) == WP_ALPHA_MASK) {
    return alpha >= materialAlphaCutoff(m);
  }
  return coverageUniform(seed, instance, primitive) < alpha;
}

WP_END

#endif
