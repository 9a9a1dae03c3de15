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

// Shadow rays stop this fraction short of the light sample so the light itself does not
// occlude it.
#define WP_SHADOW_RAY_SHORTEN 0.9999f

WP_STRUCT(ShadeResult)
  vec3 radiance;     // added to the path's pixel now
  uint flags;        // WP_SHADE_* bits
  PathRay next;      // continuation of the path
  ShadowRay shadow;  // light sample to test for visibility
WP_STRUCT_END(ShadeResult)

WP_FN vec3 xyz(vec4 v) { return make_vec3(v.x, v.y, v.z); }

// The biased contribution clamp (RenderParams.contributionClamp, 0 = off) on what a path
// adds after its first vertex; light seen directly by the camera is never clamped.
WP_FN vec3 clampedContribution(RenderParams params, vec3 c) {
  float limit = params.contributionClamp;
  return limit > 0.0f ? clampContribution(c, limit) : c;
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
  if (bsdfPdfOfRay > 0.0f && skyChoice > 0.0f) {
    uint mode = params.mode;
    if (mode == WP_MODE_NEE) {
      weight = 0.0f;
    } else if (mode == WP_MODE_MIS) {
      float skyPdf = skyChoice * environmentPdf(WP_BUFFERS_ARG params.sky, direction);
      weight = balanceHeuristic(bsdfPdfOfRay, skyPdf);
    }
  }
  r.radiance = rayThroughput(ray) * environmentRadiance(WP_BUFFERS_ARG params.sky, direction) * weight;
  if (rayBounce(ray) > 0u) {
    r.radiance = clampedContribution(params, r.radiance);
  }
  return r;
}

// The material at the hit with its vertex colour and textures applied (glTF: base colour
// times COLOR_0 times the texture; metallic and roughness times the texture's blue and
// green; emission times the emissive texture). Surfaces without TEXCOORD_0 (and spheres and
// planes) use the constant factors.
WP_FN GpuMaterial texturedMaterial(WP_BUFFERS GpuMaterial m, SurfaceHit s) {
  m.baseColor = m.baseColor * s.color;
  if (!s.hasUv) {
    return m;
  }
  vec3 emission = texturedEmission(WP_BUFFERS_ARG xyz(m.emission), m.emissiveMap.x, s.hasUv, s.uv);
  m.emission = make_vec4(emission.x, emission.y, emission.z, m.emission.w);
  if (m.info.y != WP_INVALID) {
    m.baseColor = m.baseColor * sampleTexture(WP_BUFFERS_ARG m.info.y, s.uv);
  }
  if (m.info.z != WP_INVALID) {
    vec4 t = sampleTexture(WP_BUFFERS_ARG m.info.z, s.uv);
    m.surface.x *= t.z;
    m.surface.y *= t.y;
  }
  return m;
}

// The shading normal tilted by the material's normal texture (glTF: tangent-space, +X along
// the tangent, +Y "up" in the image, xy scaled by the texture's scale). The frame is the
// file's TANGENT or else the triangle's own uv gradient (SurfaceHit), orthogonalized against
// the interpolated normal. Falls back to the unmapped normal where there is no frame or the
// result would face away from the geometric front.
WP_FN vec3 normalMapped(WP_BUFFERS GpuMaterial m, SurfaceHit s) {
  if (m.info.w == WP_INVALID || !s.hasUv) {
    return s.shadingNormal;
  }
  vec4 t = sampleTexture(WP_BUFFERS_ARG m.info.w, s.uv);
  float scale = m.normalMap.x;
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

// True when wi is on the same side of the geometric surface as wo (product of the two
// geometric cosines > 0) exactly when it is on the same side of the shading frame
// (product of the local cosines > 0): reflection stays reflection.
WP_FN bool sidesAgree(float woGeometric, float wiGeometric, float localProduct) {
  return (woGeometric * wiGeometric > 0.0f) == (localProduct > 0.0f);
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
WP_FN ShadeResult shadeHit(WP_BUFFERS RenderParams params, PathRay ray, float t, uint instanceField,
                           uint primitive) {
  ShadeResult r;
  r.flags = 0u;
  r.radiance = make_vec3(0.0f, 0.0f, 0.0f);
  vec3 direction = rayDirection(ray);
  vec3 throughput = rayThroughput(ray);
  float bsdfPdfOfRay = rayBsdfPdf(ray);  // 0 for camera rays and delta samples: nothing to weigh against
  PathSamples samples = rayPathSamples(ray);
  uint samplerKind = params.samplerKind;
  uint bounce = rayBounce(ray);
  uint maxBounces = params.maxBounces;
  uint mode = params.mode;
  uint lightCount = params.lightCount;
  uint bsdfFlags = params.bsdfFlags;
  uint lightSelection = params.lightSelection;

  float time = rayTime(ray);
  SurfaceHit s = surfaceAt(WP_BUFFERS_ARG instanceField, primitive, rayOrigin(ray) + direction * t, time);
  GpuMaterial m = texturedMaterial(WP_BUFFERS_ARG WP_LOAD(materials, s.material), s);
  s.shadingNormal = normalMapped(WP_BUFFERS_ARG m, s);
  vec3 wo = -direction;
  if (dot(s.normal, wo) < 0.0f) {
    throughput = throughput * beerLawTransmittance(xyz(m.attenuation), m.attenuation.w, t);
  }

  vec3 emission = emittedRadiance(xyz(m.emission), m.emission.w != 0.0f, s.normal, wo);
  if (maxComponent(emission) > 0.0f) {
    float weight = 1.0f;
    if (bsdfPdfOfRay > 0.0f && s.light != WP_INVALID) {
      // Next event estimation could have found this light too: weigh the two strategies.
      if (mode == WP_MODE_NEE) {
        weight = 0.0f;
      } else if (mode == WP_MODE_MIS) {
        // The selection probability as seen from the previous vertex (the ray's origin),
        // times the chance that next event estimation chose the triangles over the sky.
        GpuLight light = WP_LOAD(lights, s.light);
        float selection = (1.0f - params.sky.selectionProbability) *
                          lightSelectionProbability(WP_BUFFERS_ARG lightCount, lightSelection, light,
                                                    rayOrigin(ray), time);
        weight = balanceHeuristic(bsdfPdfOfRay, lightPdf(light, selection, t * t, dot(s.normal, wo)));
      }
    }
    r.radiance = throughput * emission * weight;
    if (bounce > 0u) {
      r.radiance = clampedContribution(params, r.radiance);
    }
  }
  if (bounce > maxBounces) {
    return r;
  }

  // Smooth shading: the BSDF sees the interpolated normal, but whether a direction is
  // reflected or transmitted is decided by the geometric normal, so no light leaks through
  // the surface (a direction whose two verdicts differ contributes nothing, to every
  // strategy alike). Where wo itself is on different sides of the two, the vertex normals
  // are unusable there and the point shades flat.
  float woSide = dot(s.normal, wo);
  vec3 shadingNormal = woSide * dot(s.shadingNormal, wo) > 0.0f ? s.shadingNormal : s.normal;
  Frame frame = makeFrame(shadingNormal);
  vec3 woLocal = frameToLocal(frame, wo);

  // Light sampling, in every mode but BSDF-only; there it still reaches the punctual lights,
  // which no BSDF sample can hit, and leaves the rest to BSDF sampling.
  float skyChoice = params.sky.selectionProbability;
  uint punctualLights = params.punctualLightCount;
  if ((mode != WP_MODE_BSDF || punctualLights > 0u) && (lightCount > 0u || skyChoice > 0.0f)) {
    PathDraw3 lightDraw = drawPath3(samplerKind, samples, vertexDimension(bounce) + WP_DIM_LIGHT_CHOICE);
    samples = lightDraw.samples;
    vec3 u = lightDraw.u;
    // The sky or the triangles, chosen in proportion to their power (packScene); u.x is
    // reused, rescaled, to select the triangle.
    LightSample ls;
    if (u.x < skyChoice) {
      ls = sampleEnvironment(WP_BUFFERS_ARG params.sky, make_vec2(u.y, u.z));
      ls.pdf *= skyChoice;
    } else {
      float select = min((u.x - skyChoice) / (1.0f - skyChoice), 0.99999994f);
      ls = sampleLight(WP_BUFFERS_ARG lightCount, lightSelection, s.position, time,
                       make_vec3(select, u.y, u.z));
      ls.pdf *= 1.0f - skyChoice;
    }
    if (mode == WP_MODE_BSDF && !ls.isDelta) {
      ls.pdf = 0.0f;
    }
    BsdfEval e = noEval();
    if (ls.pdf > 0.0f) {
      vec3 wiLocal = frameToLocal(frame, ls.direction);
      if (sidesAgree(woSide, dot(s.normal, ls.direction), woLocal.z * wiLocal.z)) {
        e = evalBsdf(m, woLocal, wiLocal, bsdfFlags);
      }
    }
    vec3 unshadowed = e.fCos * ls.radiance;
    if (maxComponent(unshadowed) > 0.0f) {
      float weight = mode == WP_MODE_MIS && !ls.isDelta ? balanceHeuristic(ls.pdf, e.pdf) : 1.0f;
      vec3 origin = offsetRayOrigin(s.position, s.normal, ls.direction);
      r.shadow.origin = make_vec4(origin.x, origin.y, origin.z, ray.origin.w);
      r.shadow.direction = make_vec4(ls.direction.x, ls.direction.y, ls.direction.z,
                                     ls.distance * WP_SHADOW_RAY_SHORTEN);
      vec3 c = clampedContribution(params, throughput * unshadowed * (weight / ls.pdf));
      r.shadow.contribution = make_vec4(c.x, c.y, c.z, time);
      r.flags |= WP_SHADE_SHADOW;
    }
  }

  // From the last vertex a ray is still traced, only to collect emission the light sample
  // did not cover: with MIS, what BSDF sampling weighs in; with BSDF sampling, all of it;
  // with NEE alone, what only a delta lobe reaches.
  PathDraw3 bsdfDraw = drawPath3(samplerKind, samples, vertexDimension(bounce) + WP_DIM_BSDF_LOBE);
  samples = bsdfDraw.samples;
  MaterialSample bs = sampleBsdf(m, woLocal, bsdfDraw.u, bsdfFlags);
  bool isDelta = (bs.flags & WP_SAMPLE_DELTA) != 0u;
  if (bounce < maxBounces || mode != WP_MODE_NEE || isDelta) {
    vec3 nextThroughput = throughput * bs.weight;
    float survival = 1.0f;
    if (bounce >= params.rouletteStart) {
      // Russian roulette: keep the path with probability max(throughput), clamped to 1.
      survival = min(1.0f, maxComponent(nextThroughput));
      PathDraw1 roulette = drawPath1(samplerKind, samples, vertexDimension(bounce) + WP_DIM_ROULETTE);
      samples = roulette.samples;
      if (roulette.u >= survival) {
        survival = 0.0f;
      }
    }
    vec3 wi = frameToWorld(frame, bs.wi);
    bool agrees = sidesAgree(woSide, dot(s.normal, wi), woLocal.z * bs.wi.z);
    if (bs.pdf > 0.0f && agrees && survival > 0.0f && maxComponent(nextThroughput) > 0.0f) {
      vec3 origin = offsetRayOrigin(s.position, s.normal, wi);
      nextThroughput = nextThroughput / survival;
      float rayPdf = isDelta ? 0.0f : bs.pdf;
      r.next = makePathRay(origin, rayPathSlot(ray), wi, rayPdf, nextThroughput, time, samples, bounce + 1u);
      r.flags |= WP_SHADE_EXTEND;
    }
  }
  return r;
}

WP_END

#endif
