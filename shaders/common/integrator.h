// The path tracer's per-vertex logic, written once for every backend: emission with its
// MIS weight, next event estimation, BSDF sampling and Russian roulette. The stage kernels
// only move rays between queues; everything an estimator depends on is here.
#ifndef WP_INTEGRATOR_H
#define WP_INTEGRATOR_H

#include "bsdf.h"
#include "environment.h"
#include "layout.h"
#include "lights.h"
#include "rng.h"
#include "sampling.h"
#include "surface.h"

WP_BEGIN

#ifdef WP_BUFFERS_AS_ARGUMENTS
#define WP_SHADING_BUFFERS WP_SURFACE_BUFFERS WP_GLOBAL_PTR(GpuMaterial) materials, WP_LIGHT_BUFFER WP_ENV_BUFFERS
#define WP_SHADING_BUFFER_ARGS WP_SURFACE_BUFFER_ARGS materials, WP_LIGHT_BUFFER_ARG WP_ENV_BUFFER_ARGS
#else
#define WP_SHADING_BUFFERS
#define WP_SHADING_BUFFER_ARGS
#endif

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

// A ray that left the scene sees the sky. Next event estimation samples the sky with
// probability sky.transform.z, so a BSDF-sampled ray's sky radiance is weighed against that.
WP_FN ShadeResult shadeMiss(WP_SHADING_BUFFERS RenderParams params, PathRay ray) {
  ShadeResult r;
  r.flags = 0u;
  vec3 direction = xyz(ray.direction);
  float bsdfPdfOfRay = ray.direction.w;  // 0 for camera rays: nothing to weigh against
  float skyChoice = params.sky.transform.z;
  float weight = 1.0f;
  if (bsdfPdfOfRay > 0.0f && skyChoice > 0.0f) {
    uint mode = params.mode.y;
    if (mode == WP_MODE_NEE) {
      weight = 0.0f;
    } else if (mode == WP_MODE_MIS) {
      float skyPdf = skyChoice * environmentPdf(WP_ENV_CDF_BUFFER_ARGS params.sky, direction);
      weight = balanceHeuristic(bsdfPdfOfRay, skyPdf);
    }
  }
  r.radiance = xyz(ray.throughput) * environmentRadiance(WP_ENV_RADIANCE_BUFFER_ARG params.sky, direction) * weight;
  return r;
}

// Bounce numbering follows Cycles' "max bounces": the camera ray hits the vertex of bounce
// 0, and with params.mode.x = D the path gathers light at vertices 0..D (next event
// estimation there, or emission found by the ray leaving them), so D = 0 is direct light.
WP_FN ShadeResult shadeHit(WP_SHADING_BUFFERS RenderParams params, PathRay ray, float t, uint instanceField,
                           uint primitive) {
  ShadeResult r;
  r.flags = 0u;
  r.radiance = make_vec3(0.0f, 0.0f, 0.0f);
  vec3 direction = xyz(ray.direction);
  vec3 throughput = xyz(ray.throughput);
  float bsdfPdfOfRay = ray.direction.w;  // 0 for camera rays: nothing to weigh against
  uint rng = ray.state.x;
  uint bounce = ray.state.y;
  uint maxBounces = params.mode.x;
  uint mode = params.mode.y;
  uint lightCount = params.mode.w;

  SurfaceHit s = surfaceAt(WP_SURFACE_BUFFER_ARGS instanceField, primitive, xyz(ray.origin) + direction * t);
  GpuMaterial m = WP_MATERIAL(s.material);
  vec3 wo = -direction;

  vec3 emission = emittedRadiance(xyz(m.emission), m.emission.w != 0.0f, s.normal, wo);
  if (maxComponent(emission) > 0.0f) {
    float weight = 1.0f;
    if (bsdfPdfOfRay > 0.0f && s.light != WP_INVALID) {
      // Next event estimation could have found this light too: weigh the two strategies.
      if (mode == WP_MODE_NEE) {
        weight = 0.0f;
      } else if (mode == WP_MODE_MIS) {
        float pdf = (1.0f - params.sky.transform.z) * lightPdf(WP_LIGHT(s.light), t * t, dot(s.normal, wo));
        weight = balanceHeuristic(bsdfPdfOfRay, pdf);
      }
    }
    r.radiance = throughput * emission * weight;
  }
  if (bounce > maxBounces) {
    return r;
  }

  Frame frame = makeFrame(dot(s.normal, wo) >= 0.0f ? s.normal : -s.normal);
  vec3 woLocal = frameToLocal(frame, wo);

  float skyChoice = params.sky.transform.z;
  if (mode != WP_MODE_BSDF && (lightCount > 0u || skyChoice > 0.0f)) {
    rng = rngNext(rng);
    float u0 = rngFloat(rng);
    rng = rngNext(rng);
    float u1 = rngFloat(rng);
    rng = rngNext(rng);
    float u2 = rngFloat(rng);
    // The sky or the triangles, chosen in proportion to their power (packScene); u0 is
    // reused, rescaled, to select the triangle.
    LightSample ls;
    if (u0 < skyChoice) {
      ls = sampleEnvironment(WP_ENV_BUFFER_ARGS params.sky, make_vec2(u1, u2));
      ls.pdf *= skyChoice;
    } else {
      float u = min((u0 - skyChoice) / (1.0f - skyChoice), 0.99999994f);
      ls = sampleLight(WP_LIGHT_BUFFER_ARG lightCount, s.position, make_vec3(u, u1, u2));
      ls.pdf *= 1.0f - skyChoice;
    }
    vec3 wiLocal = frameToLocal(frame, ls.direction);
    vec3 unshadowed = ls.pdf > 0.0f ? bsdfEvalCos(m, woLocal, wiLocal) * ls.radiance : make_vec3(0.0f, 0.0f, 0.0f);
    if (maxComponent(unshadowed) > 0.0f) {
      float weight = mode == WP_MODE_MIS ? balanceHeuristic(ls.pdf, bsdfPdf(m, woLocal, wiLocal)) : 1.0f;
      vec3 origin = offsetRayOrigin(s.position, s.normal, ls.direction);
      r.shadow.origin = make_vec4(origin.x, origin.y, origin.z, ray.origin.w);
      r.shadow.direction = make_vec4(ls.direction.x, ls.direction.y, ls.direction.z,
                                     ls.distance * WP_SHADOW_RAY_SHORTEN);
      vec3 c = throughput * unshadowed * (weight / ls.pdf);
      r.shadow.contribution = make_vec4(c.x, c.y, c.z, 0.0f);
      r.flags |= WP_SHADE_SHADOW;
    }
  }

  // From the last vertex a ray is still traced, only to collect emission the light sample
  // did not cover (MIS) or all of it (BSDF sampling); with NEE alone it would find nothing.
  if (bounce < maxBounces || mode != WP_MODE_NEE) {
    rng = rngNext(rng);
    float u0 = rngFloat(rng);
    rng = rngNext(rng);
    float u1 = rngFloat(rng);
    BsdfSample bs = bsdfSample(m, woLocal, make_vec2(u0, u1));
    vec3 nextThroughput = throughput * bs.weight;
    float survival = 1.0f;
    if (bounce >= params.mode.z) {
      // Russian roulette: keep the path with probability max(throughput), clamped to 1.
      survival = min(1.0f, maxComponent(nextThroughput));
      rng = rngNext(rng);
      if (rngFloat(rng) >= survival) {
        survival = 0.0f;
      }
    }
    if (bs.pdf > 0.0f && survival > 0.0f && maxComponent(nextThroughput) > 0.0f) {
      vec3 wi = frameToWorld(frame, bs.wi);
      vec3 origin = offsetRayOrigin(s.position, s.normal, wi);
      nextThroughput = nextThroughput / survival;
      r.next.origin = make_vec4(origin.x, origin.y, origin.z, ray.origin.w);
      r.next.direction = make_vec4(wi.x, wi.y, wi.z, bs.pdf);
      r.next.throughput = make_vec4(nextThroughput.x, nextThroughput.y, nextThroughput.z, 0.0f);
      r.next.state = make_uvec4(rng, bounce + 1u, 0u, 0u);
      r.flags |= WP_SHADE_EXTEND;
    }
  }
  return r;
}

WP_END

#endif
