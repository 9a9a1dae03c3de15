// The path tracer's per-vertex logic, written once for every backend: emission with its
// MIS weight, next event estimation, BSDF sampling and Russian roulette. The stage kernels
// only move rays between queues; everything an estimator depends on is here.
#ifndef WP_INTEGRATOR_H
#define WP_INTEGRATOR_H

#include "binding_table.h"
#include "bsdf.h"
#include "environment.h"
#include "lights.h"
#include "sampler.h"
#include "sampling.h"
#include "surface.h"
#include "texture.h"

WP_BEGIN

#define WP_SHADE_EXTEND 1u  // ShadeResult.next is a ray to trace
#define WP_SHADE_SHADOW 2u  // ShadeResult.shadow is a shadow ray to trace
#define WP_SHADE_FEATURES 4u  // ShadeResult.features are the path's feature passes (see shadeHit)

// The depth pass of a camera ray that leaves the scene: far, as the sky is, yet finite, so
// that a pixel's mean over samples that hit and samples that miss stays a number.
#define WP_DEPTH_MISS 1e10f

// Shadow rays stop this fraction short of the light sample so the light itself does not
// occlude it.
#define WP_SHADOW_RAY_SHORTEN 0.9999f

WP_STRUCT(ShadeResult)
  vec3 radiance;     // added to the path's pixel now
  uint flags;        // WP_SHADE_* bits
  PathRay next;      // continuation of the path
  ShadowRay shadow;  // light sample to test for visibility
  PathFeatures features;  // with WP_SHADE_FEATURES; its depth counts at bounce 0 only
WP_STRUCT_END(ShadeResult)

WP_FN vec3 xyz(vec4 v) { return make_vec3(v.x, v.y, v.z); }

// The biased contribution clamp (RenderParams.contributionClamp, 0 = off) on what a path
// adds after its first vertex; light seen directly by the camera is never clamped.
WP_FN vec3 clampedContribution(RenderParams params, vec3 c) {
  float limit = params.contributionClamp;
  return limit > 0.0f ? clampContribution(c, limit) : c;
}

// ---- Filter glossy (RenderParams.filterGlossy, 0 = off): biased, as Cycles' ------------
// A diffuse bounce followed by a sharp glossy one that then finds a small light (the sun's
// highlight on a glossy sphere, seen from the ground) is a path that BSDF sampling finds
// rarely and next event estimation weighs hugely: fireflies that converge slowly. Cycles
// blurs such lobes, and its default (Filter Glossy 1) is what a Blender user compares
// with; wavepath does the same on request, with Cycles' rule and meaning of the value
// (surface_shader_prepare_closures, Cycles 3.4): the least pdf p of the path's BSDF samples
// so far (delta samples excluded), and where p / filterGlossy < 1 every microfacet lobe's
// alpha at least sqrt(1 - p / filterGlossy) / 2. A camera ray's first vertex and what only
// delta bounces led to are never blurred.

// p is carried in the ray's 16 spare flag bits (layout.h) as the upper half of its float's
// bits: for positive floats those order as the floats do, so the least of them is that of
// the least pdf, cut to 8 bits of mantissa (a heuristic's input), the same on every backend.
WP_FN uint leastPdfBitsAfter(uint leastPdfBits, float pdf) {
  uint bits = max(asUint(pdf) >> 16u, 1u);  // 0 means none yet
  return leastPdfBits == 0u ? bits : min(leastPdfBits, bits);
}

// The least pdf that leastPdfBits (not 0) holds.
WP_FN float leastPdfOf(uint leastPdfBits) { return asFloat(leastPdfBits << 16u); }

// The perceptual roughness (sqrt of alpha) every microfacet lobe of the vertex gets at least,
// for a path whose least BSDF-sample pdf so far is leastPdfBits; 0: none.
WP_FN float glossyFloorRoughness(RenderParams params, uint leastPdfBits) {
  if (!(params.filterGlossy > 0.0f) || leastPdfBits == 0u) {
    return 0.0f;
  }
  float blurPdf = leastPdfOf(leastPdfBits) / params.filterGlossy;
  return blurPdf < 1.0f ? sqrt(0.5f * sqrt(1.0f - blurPdf)) : 0.0f;
}

// A ray that left the scene sees the sky. Next event estimation samples the sky with
// probability sky.selectionProbability, so a BSDF-sampled ray's sky radiance is weighed
// against that.
WP_FN ShadeResult shadeMiss(WP_BUFFERS RenderParams params, PathRay ray) {
  ShadeResult r;
  r.flags = 0u;
  vec3 direction = rayDirection(ray);
  float bsdfPdfOfRay = rayBsdfPdf(ray);  // 0 for camera rays: nothing to weigh against
  float skyChoice = params.sky.selectionProbability;
  float weight = 1.0f;
  if (WP_SCENE_SKY_SAMPLED && bsdfPdfOfRay > 0.0f && skyChoice > 0.0f) {
    uint mode = params.mode;
    if (mode == WP_MODE_NEE) {
      weight = 0.0f;
    } else if (mode == WP_MODE_MIS) {
      float skyPdf = skyChoice * environmentPdf(WP_BUFFERS_ARG params.sky, direction);
      weight = balanceHeuristic(bsdfPdfOfRay, skyPdf);
    }
  }
  vec3 sky = environmentRadiance(WP_BUFFERS_ARG params.sky, direction);
  r.radiance = rayThroughput(ray) * sky * weight;
  if (rayBounce(ray) > 0u) {
    r.radiance = clampedContribution(params, r.radiance);
  }
  if (recordsFeaturePasses(params) && !rayFeaturesTaken(ray)) {
    // The sky's albedo is its radiance clamped to [0, 1], so that a denoiser sees the edges
    // of what stands against it; it has no normal.
    vec3 skyAlbedo = clamp(sky, make_vec3(0.0f, 0.0f, 0.0f), make_vec3(1.0f, 1.0f, 1.0f));
    r.features = makePathFeatures(skyAlbedo, make_vec3(0.0f, 0.0f, 0.0f), WP_DEPTH_MISS);
    r.flags |= WP_SHADE_FEATURES;
  }
  return r;
}

// The texture `index` at the hit, or 1 where there is none or the surface lacks its
// coordinate set (the factor alone).
WP_FN vec4 textureOrOne(WP_BUFFERS uint index, TexCoords c) {
  return textureApplies(WP_BUFFERS_ARG index, c) ? sampleTexture(WP_BUFFERS_ARG index, c)
                                                 : make_vec4(1.0f, 1.0f, 1.0f, 1.0f);
}

// The layered extensions' factors times their textures (layout.h says which channel).
WP_FN_INLINED GpuMaterial texturedLayers(WP_BUFFERS GpuMaterial m, TexCoords c) {
  vec4 specularColor = textureOrOne(WP_BUFFERS_ARG materialSpecularColorTexture(m), c);
  float specular = textureOrOne(WP_BUFFERS_ARG materialSpecularTexture(m), c).w;
  m.specular = m.specular * make_vec4(specularColor.x, specularColor.y, specularColor.z, specular);
  if (!WP_SCENE_LAYERED) {
    return m;
  }
  vec4 sheenColor = textureOrOne(WP_BUFFERS_ARG materialSheenColorTexture(m), c);
  float sheenRoughness = textureOrOne(WP_BUFFERS_ARG materialSheenRoughnessTexture(m), c).w;
  m.sheen = m.sheen * make_vec4(sheenColor.x, sheenColor.y, sheenColor.z, sheenRoughness);
  m.clearcoat.x *= textureOrOne(WP_BUFFERS_ARG materialClearcoatTexture(m), c).x;
  m.clearcoat.y *= textureOrOne(WP_BUFFERS_ARG materialClearcoatRoughnessTexture(m), c).y;
  return m;
}

// The material at the hit with its vertex colour and textures applied (glTF: base colour
// times COLOR_0 times the texture; metallic and roughness times the texture's blue and
// green; emission times the emissive texture; the layered extensions' factors times their
// textures' channels, as layout.h lists them), each texture on its own coordinate set and
// transform. Where the surface lacks a texture's set (spheres and planes have none) its
// factor stands alone. An unlit material's emission is its base colour.
WP_FN_INLINED GpuMaterial texturedMaterial(WP_BUFFERS GpuMaterial m, SurfaceHit s) {
  m.baseColor = m.baseColor * s.color;
  TexCoords c = s.texCoords;
  vec3 emission = texturedEmission(WP_BUFFERS_ARG xyz(m.emission), materialEmissiveTexture(m), c);
  m.emission = make_vec4(emission.x, emission.y, emission.z, m.emission.w);
  if (textureApplies(WP_BUFFERS_ARG materialBaseColorTexture(m), c)) {
    m.baseColor = m.baseColor * sampleTexture(WP_BUFFERS_ARG materialBaseColorTexture(m), c);
  }
  if (textureApplies(WP_BUFFERS_ARG materialMetallicRoughnessTexture(m), c)) {
    vec4 t = sampleTexture(WP_BUFFERS_ARG materialMetallicRoughnessTexture(m), c);
    m.surface.x *= t.z;
    m.surface.y *= t.y;
  }
  m = texturedLayers(WP_BUFFERS_ARG m, c);
  if (materialKind(m) == WP_MATERIAL_UNLIT) {
    m.emission = make_vec4(m.baseColor.x, m.baseColor.y, m.baseColor.z, m.emission.w);
  }
  return m;
}

// The shading normal tilted by a normal texture of the material (glTF: tangent-space, +X
// along the tangent, +Y "up" in the image, xy scaled by the texture's scale). The frame is the
// file's TANGENT or else the triangle's own uv gradient (SurfaceHit), orthogonalized against
// the interpolated normal. Falls back to the unmapped normal where there is no frame or the
// result would face away from the geometric front.
WP_FN vec3 normalMapped(WP_BUFFERS uint texture, float scale, SurfaceHit s) {
  if (!textureApplies(WP_BUFFERS_ARG texture, s.texCoords)) {
    return s.shadingNormal;
  }
  vec4 t = sampleTexture(WP_BUFFERS_ARG texture, s.texCoords);
  vec3 tangentSpace = make_vec3((2.0f * t.x - 1.0f) * scale, (2.0f * t.y - 1.0f) * scale, 2.0f * t.z - 1.0f);
  vec3 n = s.shadingNormal;
  vec3 tangent = s.tangent - n * dot(n, s.tangent);
  vec3 bitangent = s.bitangent - n * dot(n, s.bitangent) - tangent * (dot(tangent, s.bitangent) / max(dot(tangent, tangent), 1e-20f));
  if (dot(tangent, tangent) < 1e-12f || dot(bitangent, bitangent) < 1e-12f || dot(tangentSpace, tangentSpace) < 1e-12f) {
    return n;
  }
  vec3 mapped = normalize(normalize(tangent) * tangentSpace.x + normalize(bitangent) * tangentSpace.y + n * tangentSpace.z);
  return dot(mapped, s.normal) > 0.0f ? mapped : n;
}

// The clear coat's normal in the local shading frame: the interpolated normal tilted by the
// coat's own normal texture (glTF: the coat ignores the base's normal texture). A coat whose
// normal would not face wo's side of the frame lies flat on the shading normal instead.
WP_FN vec4 localCoatNormal(WP_BUFFERS GpuMaterial m, SurfaceHit s, Frame frame) {
  if (!WP_SCENE_LAYERED || !(materialClearcoat(m) > 0.0f)) {
    return make_vec4(0.0f, 0.0f, 1.0f, 0.0f);
  }
  vec3 n = frameToLocal(frame, normalMapped(WP_BUFFERS_ARG materialClearcoatNormalTexture(m),
                                            materialClearcoatNormalScale(m), s));
  return n.z > WP_BSDF_MIN_COS ? make_vec4(n.x, n.y, n.z, 0.0f) : make_vec4(0.0f, 0.0f, 1.0f, 0.0f);
}

// True when wi is on the same side of the geometric surface as wo (product of the two
// geometric cosines > 0) exactly when it is on the same side of the shading frame
// (product of the local cosines > 0): reflection stays reflection.
WP_FN bool sidesAgree(float woGeometric, float wiGeometric, float localProduct) {
  return (woGeometric * wiGeometric > 0.0f) == (localProduct > 0.0f);
}

// A path at the surface vertex it reached, as the shading functions below read it.
WP_STRUCT(PathVertex)
  vec3 position;    // on the surface
  vec3 normal;      // geometric, unit
  Frame frame;      // the shading frame the BSDF sees (pathVertexAt)
  vec3 woLocal;     // back along the ray, in `frame`
  float woSide;     // dot(normal, wo): reflection and transmission are told apart by it
  vec3 throughput;  // of the path up to here, the medium it crossed included
  float time;       // the path's shutter time
  uint pathSlot;
  uint bounce;
  uint rayFlags;    // WP_RAY_* flags the continuation carries
  uint leastPdfBits;  // the least pdf of the path's BSDF samples so far (leastPdfBitsAfter)
WP_STRUCT_END(PathVertex)

// What a vertex may send on: the path's continuation, and its light sample's shadow ray
// (`exists` is false where there is none).
WP_STRUCT(NextRay)
  bool exists;
  PathRay ray;
WP_STRUCT_END(NextRay)
WP_STRUCT(ShadowConnection)
  bool exists;
  ShadowRay ray;
WP_STRUCT_END(ShadowConnection)

// Smooth shading: the BSDF sees the interpolated normal, but whether a direction is
// reflected or transmitted is decided by the geometric normal, so no light leaks through
// the surface (a direction whose two verdicts differ contributes nothing, to every
// strategy alike: sidesAgree). Where wo itself is on different sides of the two, the vertex
// normals are unusable there and the point shades flat.
WP_FN_INLINED PathVertex pathVertexAt(SurfaceHit s, vec3 wo, vec3 throughput, PathRay ray) {
  PathVertex v;
  v.position = s.position;
  v.normal = s.normal;
  v.woSide = dot(s.normal, wo);
  vec3 shadingNormal = v.woSide * dot(s.shadingNormal, wo) > 0.0f ? s.shadingNormal : s.normal;
  v.frame = makeFrame(shadingNormal);
  v.woLocal = frameToLocal(v.frame, wo);
  v.throughput = throughput;
  v.time = rayTime(ray);
  v.pathSlot = rayPathSlot(ray);
  v.bounce = rayBounce(ray);
  v.rayFlags = rayFlagsOf(ray);
  v.leastPdfBits = rayLeastPdfBits(ray);
  return v;
}

// The MIS weight of emission that `ray` found at distance t on the emitter of s: next event
// estimation could have found that light too (a delta BSDF sample, whose ray has pdf 0,
// could not, nor could a camera ray).
WP_FN_INLINED float emissionMisWeight(WP_BUFFERS RenderParams params, PathRay ray, SurfaceHit s, vec3 wo, float t) {
  float weight = 1.0f;
  float bsdfPdfOfRay = rayBsdfPdf(ray);
  if (bsdfPdfOfRay > 0.0f && s.light != WP_INVALID) {
    uint mode = params.mode;
    if (mode == WP_MODE_NEE) {
      weight = 0.0f;
    } else if (mode == WP_MODE_MIS) {
      // The selection probability as seen from the previous vertex (the ray's origin),
      // times the chance that next event estimation chose the triangles over the sky.
      GpuLight light = WP_LOAD(lights, s.light);
      float selection = (1.0f - params.sky.selectionProbability) *
                        lightSelectionProbability(WP_BUFFERS_ARG params.lightCount, params.lightSelection, light,
                                                  rayOrigin(ray), rayTime(ray));
      weight = balanceHeuristic(bsdfPdfOfRay, lightPdf(light, selection, t * t, dot(s.normal, wo)));
    }
  }
  return weight;
}

// The light the path finds at the hit (material m at s, reached by `ray` at distance t,
// seen from wo), weighted against next event estimation.
WP_FN_INLINED vec3 emissionAtHit(WP_BUFFERS RenderParams params, PathRay ray, SurfaceHit s, GpuMaterial m, vec3 wo,
                         vec3 throughput, float t) {
  if (!WP_SCENE_EMISSIVE) {  // (no material emits: Vulkan and OpenCL compile the rest away)
    return make_vec3(0.0f, 0.0f, 0.0f);
  }
  vec3 emission = emittedRadiance(xyz(m.emission), m.emission.w != 0.0f, s.normal, wo);
  if (!(maxComponent(emission) > 0.0f)) {
    return make_vec3(0.0f, 0.0f, 0.0f);
  }
  vec3 radiance = throughput * emission * emissionMisWeight(WP_BUFFERS_ARG params, ray, s, wo, t);
  return rayBounce(ray) > 0u ? clampedContribution(params, radiance) : radiance;
}

// Whether shade draws a light sample: in every mode but BSDF-only, where it still reaches
// the punctual lights, which no BSDF sample can hit, and leaves the rest to BSDF sampling.
WP_FN_INLINED bool samplesLights(RenderParams params) {
  return (params.mode != WP_MODE_BSDF || params.punctualLightCount > 0u) &&
         (params.lightCount > 0u || params.sky.selectionProbability > 0.0f);
}

// A point on the sky or on the lights for next event estimation from `position`: the sky
// or the lights chosen in proportion to their power (packScene), u.x reused, rescaled, to
// select the light; its pdf includes that choice.
WP_FN_INLINED LightSample sampleSkyOrLight(WP_BUFFERS RenderParams params, vec3 position, float time, vec3 u) {
  float skyChoice = params.sky.selectionProbability;
  LightSample ls;
  // (WP_SCENE_SKY_SAMPLED false: skyChoice is 0, and Vulkan and OpenCL compile the sky's sampling away.)
  if (WP_SCENE_SKY_SAMPLED && u.x < skyChoice) {
    ls = sampleEnvironment(WP_BUFFERS_ARG params.sky, make_vec2(u.y, u.z));
    ls.pdf *= skyChoice;
  } else {
    float select = min((u.x - skyChoice) / (1.0f - skyChoice), 0.99999994f);
    ls = sampleLight(WP_BUFFERS_ARG params.lightCount, params.lightSelection, position, time,
                     make_vec3(select, u.y, u.z));
    ls.pdf *= 1.0f - skyChoice;
  }
  return ls;
}

// Next event estimation at v with random numbers u: a light sample, its BSDF value and
// MIS weight, and the shadow ray that adds it to the path if nothing blocks it (none where
// it contributes nothing). In BSDF-only mode only the punctual lights are sampled.
WP_FN_INLINED ShadowConnection sampleDirectLight(WP_BUFFERS RenderParams params, PathVertex v, GpuMaterial m, vec3 u) {
  uint mode = params.mode;
  LightSample ls = sampleSkyOrLight(WP_BUFFERS_ARG params, v.position, v.time, u);
  if (mode == WP_MODE_BSDF && !ls.isDelta) {
    ls.pdf = 0.0f;
  }
  BsdfEval e = noEval();
  if (ls.pdf > 0.0f) {
    vec3 wiLocal = frameToLocal(v.frame, ls.direction);
    if (sidesAgree(v.woSide, dot(v.normal, ls.direction), v.woLocal.z * wiLocal.z)) {
      e = evalBsdf(m, v.woLocal, wiLocal, params.bsdfFlags);
    }
  }
  ShadowConnection c;
  vec3 unshadowed = e.fCos * ls.radiance;
  c.exists = maxComponent(unshadowed) > 0.0f;
  if (c.exists) {
    float weight = mode == WP_MODE_MIS && !ls.isDelta ? balanceHeuristic(ls.pdf, e.pdf) : 1.0f;
    vec3 contribution = clampedContribution(params, v.throughput * unshadowed * (weight / ls.pdf));
    c.ray = makeShadowRay(offsetRayOrigin(v.position, v.normal, ls.direction), v.pathSlot, ls.direction,
                          ls.distance * WP_SHADOW_RAY_SHORTEN, contribution, v.time);
  }
  return c;
}

// Russian roulette on a path whose throughput becomes `throughput` past v: from
// params.rouletteStart on, it survives with probability max(throughput), clamped to 1,
// decided by the vertex's roulette number `u`. The survival probability (0: the path ends).
WP_FN_INLINED float russianRoulette(RenderParams params, uint bounce, vec3 throughput, float u) {
  float survival = 1.0f;
  if (bounce >= params.rouletteStart) {
    survival = min(1.0f, maxComponent(throughput));
    if (u >= survival) {
      survival = 0.0f;
    }
  }
  return survival;
}

// BSDF sampling and Russian roulette at v with the vertex's numbers `draws`: the
// continuation of the path, which survived Russian roulette, unless it ends here.
//
// From the last vertex a ray is still traced, only to collect emission the light sample
// did not cover: with MIS, what BSDF sampling weighs in; with BSDF sampling, all of it;
// with NEE alone, what only a delta lobe reaches; and, where the render records them, the
// feature passes of a path whose vertices so far were all perfectly specular (what a mirror
// shows, shadeHit). Where nothing a ray can hit emits (params.emissionHittable 0: lamps
// alone, a black sky) and the features are taken or not recorded, that ray would add
// exactly nothing, and it is not traced: the image and its passes are the same, without the
// extend and shade work (40% of the extension rays of a direct-light render, --max-depth 0,
// of the instanced scene).
WP_FN_INLINED NextRay sampleContinuation(RenderParams params, PathVertex v, GpuMaterial m, VertexDraws draws) {
  NextRay next;
  next.exists = false;
  MaterialSample bs = sampleBsdf(m, v.woLocal, draws.bsdf, params.bsdfFlags);
  bool isDelta = (bs.flags & WP_SAMPLE_DELTA) != 0u;
  bool collectsEmission = params.emissionHittable != 0u && (params.mode != WP_MODE_NEE || isDelta);
  bool featuresPending = recordsFeaturePasses(params) && (v.rayFlags & WP_RAY_FEATURES_TAKEN) == 0u;
  if (v.bounce < params.maxBounces || collectsEmission || featuresPending) {
    vec3 nextThroughput = v.throughput * bs.weight;
    float survival = russianRoulette(params, v.bounce, nextThroughput, draws.roulette);
    vec3 wi = frameToWorld(v.frame, bs.wi);
    bool agrees = sidesAgree(v.woSide, dot(v.normal, wi), v.woLocal.z * bs.wi.z);
    if (bs.pdf > 0.0f && agrees && survival > 0.0f && maxComponent(nextThroughput) > 0.0f) {
      vec3 origin = offsetRayOrigin(v.position, v.normal, wi);
      nextThroughput = nextThroughput / survival;
      float rayPdf = isDelta ? 0.0f : bs.pdf;
      uint leastPdfBits = isDelta ? v.leastPdfBits : leastPdfBitsAfter(v.leastPdfBits, bs.pdf);
      next.ray = makePathRay(origin, v.pathSlot, wi, rayPdf, nextThroughput, v.time, draws.samples, v.bounce + 1u,
                             v.rayFlags, leastPdfBits);
      next.exists = true;
    }
  }
  return next;
}

// Bounce numbering follows Cycles' "max bounces": the camera ray hits the vertex of bounce
// 0, and with params.maxBounces = D the path gathers light at vertices 0..D (next event
// estimation there, or emission found by the ray leaving them), so D = 0 is direct light.
//
// Delta lobes (smooth mirror and glass) cannot be light-sampled: evalBsdf gives them no
// value, so next event estimation counts only a material's other lobes, and a delta sample
// stores pdf 0 on its ray so that the emission it finds gets MIS weight 1 in every mode.
//
// Media: a ray that reaches the back side of a surface travelled inside it, so the
// material's KHR_materials_volume attenuation applies over t (Beer's law). This assumes
// closed meshes and media that do not nest or overlap.
//
// A vertex goes through: the surface and its material, emissionAtHit (with its MIS
// weight), then, below the bounce limit, sampleDirectLight (next event estimation) and
// sampleContinuation (BSDF sampling and Russian roulette), each with its own numbers from
// the path's sampler (the vertex's dimensions of sampler.h), drawn in that order.
WP_FN_INLINED ShadeResult shadeHit(WP_BUFFERS RenderParams params, PathRay ray, float t, uint instanceField,
                                   uint primitive) {
  ShadeResult r;
  r.flags = 0u;
  // The vertex's numbers first: they need only the ray, and a CPU device then computes their
  // long chain of integer multiplies while the loads of the surface and material wait on
  // memory.
  bool lightSampled = samplesLights(params);
  uint bounce = rayBounce(ray);
  VertexDraws draws =
      drawVertex(params.samplerKind, rayPathSamples(ray), bounce, lightSampled, bounce >= params.rouletteStart);
  vec3 direction = rayDirection(ray);
  vec3 throughput = rayThroughput(ray);
  SurfaceHit s = surfaceAt(WP_BUFFERS_ARG instanceField, primitive, rayOrigin(ray) + direction * t, rayTime(ray));
  GpuMaterial m = texturedMaterial(WP_BUFFERS_ARG WP_LOAD(materials, s.material), s);
  SurfaceHit unmapped = s;
  s.shadingNormal = normalMapped(WP_BUFFERS_ARG materialNormalTexture(m), m.normalMap.x, s);
  vec3 wo = -direction;
  if (dot(s.normal, wo) < 0.0f) {
    throughput = throughput * beerLawTransmittance(xyz(m.attenuation), m.attenuation.w, t);
  }

  // The feature passes (Open Image Denoise's auxiliary images, Blender's denoising data):
  // the albedo and the normal of the first vertex that is not perfectly specular (through
  // smooth mirrors and glass they are those of what the path sees in them), and the depth of
  // the camera ray's hit. The albedo is the base colour, textured: a plastic's diffuse
  // colour, a metal's reflectivity, a glass's tint. The normal is the shading normal (normal
  // map included) turned towards the ray. Only a render that keeps them records them.
  bool records = recordsFeaturePasses(params);
  bool takesFeatures = records && !rayFeaturesTaken(ray) && !bsdfIsPerfectlySpecular(m);
  if (takesFeatures || (records && bounce == 0u)) {
    vec3 n = dot(s.normal, wo) < 0.0f ? -s.shadingNormal : s.shadingNormal;
    vec3 zero = make_vec3(0.0f, 0.0f, 0.0f);
    r.features = makePathFeatures(takesFeatures ? albedoOf(m) : zero, takesFeatures ? n : zero,
                                  cameraDepth(params.camera, direction, t));
    r.flags |= WP_SHADE_FEATURES;
  }

  r.radiance = emissionAtHit(WP_BUFFERS_ARG params, ray, s, m, wo, throughput, t);
  if (bounce > params.maxBounces) {
    return r;
  }
  m = withGlossyFloor(m, glossyFloorRoughness(params, rayLeastPdfBits(ray)));

  PathVertex v = pathVertexAt(s, wo, throughput, ray);
  if (takesFeatures) {
    v.rayFlags |= WP_RAY_FEATURES_TAKEN;
  }
  m.clearcoatNormal = localCoatNormal(WP_BUFFERS_ARG m, unmapped, v.frame);
  if (lightSampled) {
    ShadowConnection shadow = sampleDirectLight(WP_BUFFERS_ARG params, v, m, draws.light);
    if (shadow.exists) {
      r.shadow = shadow.ray;
      r.flags |= WP_SHADE_SHADOW;
    }
  }
  NextRay next = sampleContinuation(params, v, m, draws);
  if (next.exists) {
    r.next = next.ray;
    r.flags |= WP_SHADE_EXTEND;
  }
  return r;
}

WP_END

#endif
