// What each wavefront stage computes for one work item, written once for the Vulkan (.comp)
// and OpenCL (.cl) kernels, so both backends trace the same paths from the same random
// numbers and keep their queues (queues.h) the same way. The kernels only add what their
// language does differently: the appends of shade, counted per subgroup or work-group.
#ifndef WP_STAGES_H
#define WP_STAGES_H

#include "accumulation.h"
#include "binding_table.h"
#include "integrator.h"
#include "queues.h"
#include "sampler.h"
#include "thin_lens.h"
#include "traverse.h"

WP_BEGIN

// The image pixel (row-major over the whole image) of pixel `regionPixel` of the region
// traced (row-major over the region).
WP_FN uint imagePixel(RenderParams params, uint regionPixel) {
  uint column = params.regionX + regionPixel % params.regionWidth;
  uint row = params.regionY + regionPixel / params.regionWidth;
  return row * params.width + column;
}

// The camera ray of path slot `slot` of the pass `pc`: slot i is pixel (firstPixel + i) %
// pixels of the region of sample firstSample + (firstPixel + i) / pixels (see
// PassConstants), through a point of that pixel (a box filter) and a point on the lens
// aperture, at a shutter time in [0, 1), all uniform, drawn by the render's sampler from
// (image pixel, sample, seed): a pixel's paths are the same whichever region or batch of
// samples traces them.
WP_FN_INLINED PathRay cameraPathRay(RenderParams params, PassConstants pc, uint slot) {
  uint pixels = params.pixelCount;
  uint linear = pc.firstPixel + slot;
  uint pixel = imagePixel(params, linear % pixels);
  uint sampleIndex = pc.firstSample + linear / pixels;

  uint samplerKind = params.samplerKind;
  PathSamples samples = startPathSamples(samplerKind, pixel, sampleIndex, params.seed);
  CameraDraws draws = drawCamera(samplerKind, samples);
  uint width = params.width;
  vec2 film = make_vec2(toFloat(pixel % width), toFloat(pixel / width)) + draws.film;
  CameraRay camera = sampleThinLensRay(params.camera, film, width, params.height, draws.lens);
  return makePathRay(camera.origin, slot, camera.direction, 0.0f, make_vec3(1.0f, 1.0f, 1.0f), draws.time,
                     draws.samples, 0u, 0u, 0u);
}

// The closest hit of `ray`, as shade reads it.
WP_FN HitRecord extendRay(WP_BUFFERS RenderParams params, PathRay ray) {
  Hit h = traceClosest(WP_BUFFERS_ARG params.topLevel, params.planeCount, rayOrigin(ray), rayDirection(ray),
                       WP_FLT_MAX, rayTime(ray));
  return makeHitRecord(h.t, h.instance, h.primitive);
}

// The vertex `ray` reached (or the sky it left to), from its hit record.
WP_FN_INLINED ShadeResult shadePath(WP_BUFFERS RenderParams params, PathRay ray, HitRecord hit) {
  if (hitIsMiss(hit)) {
    return shadeMiss(WP_BUFFERS_ARG params, ray);
  }
  return shadeHit(WP_BUFFERS_ARG params, ray, hitDistance(hit), hitInstanceField(hit), hitPrimitive(hit));
}

// Whether nothing blocks the shadow ray before its light sample.
WP_FN bool shadowRayUnoccluded(WP_BUFFERS RenderParams params, ShadowRay s) {
  return !traceAny(WP_BUFFERS_ARG params.topLevel, params.planeCount, shadowRayOrigin(s), shadowRayDirection(s),
                   shadowRayLength(s), shadowRayTime(s));
}

// Adds to the radiance of the path in `slot`: read through WP_LOAD (on Vulkan a texel view,
// one gather), written rgb only (on lavapipe every component written is a scalar store per
// lane).
WP_FN void addPathRadiance(WP_BUFFERS uint slot, vec3 radiance) {
  WP_SET_XYZ(WP_BUFFER(pathRadiance)[slot], WP_XYZ(WP_LOAD(pathRadiance, slot)) + radiance);
}

// Whether adaptive sampling stopped the pixel of path slot `slot` of the pass `pc` (as of the
// passes before it: accumulate of this pass decides for its own samples).
WP_FN bool slotPixelStopped(WP_BUFFERS RenderParams params, PassConstants pc, uint slot) {
  uint pixels = params.pixelCount;
  uint pixel = (pc.firstPixel + slot) % pixels;
  return pixelStopped(WP_LOAD(accumulation, accumulationIndex(WP_LAYER_RADIANCE_SQUARES, pixel, pixels)));
}

// Generate, work item `slot`: the camera ray of that path slot into bounce 0's ray queue,
// and the path's radiance cleared; the first work item also starts the pass's queues. With
// adaptive sampling the rays of pixels that stopped are left out and the others appended,
// so the queue holds only paths to trace (entry order does not matter: a path's results go
// to its slot).
WP_FN_INLINED void generateStage(WP_BUFFERS RenderParams params, PassConstants pc, uint slot) {
  uint pathCount = pc.pathCount;
  uint maxPaths = params.maxPaths;
  bool adaptive = params.adaptiveThreshold > 0.0f;
  if (slot == 0u) {
    startPassQueues(WP_BUFFERS_ARG pathCount, maxPaths, adaptive);
  }
  if (slot >= pathCount) {
    return;
  }
  WP_BUFFER(pathRadiance)[slot] = make_vec4(0.0f, 0.0f, 0.0f, 0.0f);
  if (adaptive && slotPixelStopped(WP_BUFFERS_ARG params, pc, slot)) {
    return;
  }
  // One camera ray written in one place: lavapipe runs both sides of a branch, and made the
  // ray twice when each side had its own (generate 20-30% longer on the box).
  WorkQueue queue = rayQueue(0u, maxPaths);
  uint entry = slot;
  if (adaptive) {
    entry = reserveQueueEntries(WP_BUFFERS_ARG queue, 1u);
  }
  WP_BUFFER(rays)[queueEntry(queue, entry)] = cameraPathRay(params, pc, slot);
}

// Extend, work item `i`: the closest hit of entry i of the bounce's ray queue, into hits[i].
WP_FN_INLINED void extendStage(WP_BUFFERS RenderParams params, PassConstants pc, uint i) {
  WorkQueue queue = rayQueue(pc.bounce, params.maxPaths);
  if (i >= queueSize(WP_BUFFERS_ARG queue)) {
    return;
  }
  WP_BUFFER(hits)[i] = extendRay(WP_BUFFERS_ARG params, WP_LOAD(rays, queueEntry(queue, i)));
}

#if WP_WORK_ITEMS_ARE_THREADS
// Where work-items are threads, a work-group's items run one after another, and shade waited
// for the triangle it reads first: the triangle and its shading record were last read by
// extend, long enough before to have left the core's caches (their first loads took a third
// of PoCL's shade samples on the instanced scene). So each work-item starts fetching the
// surface of the hit that the work-item this many places later shades.
#define WP_SHADE_PREFETCH_DISTANCE 4u
// Starts fetching the triangle and the shading record (its three cache lines) of entry j's
// hit, if j is in the queue and its hit is on a triangle.
WP_FN_INLINED void prefetchSurfaceOfHit(WP_BUFFERS WorkQueue queue, uint j) {
  if (j < queueSize(WP_BUFFERS_ARG queue)) {
    uint primitive = hitPrimitive(WP_LOAD(hits, j));
    if (primitive != WP_INVALID) {
      WP_PREFETCH(WP_LOAD(triangles, primitive).v0);
      WP_PREFETCH(WP_LOAD(triangleShading, primitive).normal0);
      WP_PREFETCH(WP_LOAD(triangleShading, primitive).colors);
      WP_PREFETCH(WP_LOAD(triangleShading, primitive).texCoord1Vertex2);
    }
  }
}
#endif

// Shade, work item `i` (below the size of the bounce's ray queue): the vertex that entry i
// reached, its radiance added to the path. The kernel appends the continuation and the
// shadow ray the result holds to continuationQueue and shadowQueue.
WP_FN_INLINED ShadeResult shadeStage(WP_BUFFERS RenderParams params, PassConstants pc, uint i) {
  WorkQueue queue = rayQueue(pc.bounce, params.maxPaths);
#if WP_WORK_ITEMS_ARE_THREADS
  prefetchSurfaceOfHit(WP_BUFFERS_ARG queue, i + WP_SHADE_PREFETCH_DISTANCE);
#endif
  PathRay ray = WP_LOAD(rays, queueEntry(queue, i));
  ShadeResult r = shadePath(WP_BUFFERS_ARG params, ray, WP_LOAD(hits, i));
  if (r.radiance.x != 0.0f || r.radiance.y != 0.0f || r.radiance.z != 0.0f) {
    addPathRadiance(WP_BUFFERS_ARG rayPathSlot(ray), r.radiance);
  }
  // Tested for the render too, so that Vulkan compiles the write away where it has none
  // (lavapipe runs a branch's body whatever its lanes chose).
  if (recordsFeaturePasses(params) && (r.flags & WP_SHADE_FEATURES) != 0u) {
    // Every path is shaded at bounce 0, which sets all its features; a later vertex that
    // takes the albedo and normal keeps that depth.
    uint slot = rayPathSlot(ray);
    PathFeatures f = r.features;
    if (rayBounce(ray) > 0u) {
      f = withDepth(f, featureDepth(WP_LOAD(pathFeatures, slot)));
    }
    WP_BUFFER(pathFeatures)[slot] = f;
  }
  return r;
}

// The queue that shade of pc.bounce appends the paths' continuations to: the next bounce's.
WP_FN WorkQueue continuationQueue(RenderParams params, PassConstants pc) {
  return rayQueue(pc.bounce + 1u, params.maxPaths);
}

// Advance, one work item: the queue sizes of `pc`'s bounce turned into the next stages'
// dispatch arguments (advanceQueues), so the pass needs no readback; or, after generate
// (WP_AFTER_GENERATE), bounce 0 sized to the camera rays generate appended.
WP_FN_INLINED void advanceStage(WP_BUFFERS RenderParams params, PassConstants pc, uint i) {
  // The dispatch is one workgroup; a single work item must do the read-modify-writes.
  if (i == 0u) {
    if (pc.bounce == WP_AFTER_GENERATE) {
      sizeFirstBounce(WP_BUFFERS_ARG params.maxPaths);
    } else {
      advanceQueues(WP_BUFFERS_ARG pc.bounce, params.maxPaths);
    }
  }
}

// Connect, work item `i`: the shadow ray at entry i of the bounce's shadow queue adds its
// light sample to its path unless something blocks it.
WP_FN_INLINED void connectStage(WP_BUFFERS RenderParams params, PassConstants pc, uint i) {
  WorkQueue queue = shadowQueue(pc.bounce);
  if (i >= queueSize(WP_BUFFERS_ARG queue)) {
    return;
  }
  ShadowRay s = WP_LOAD(shadowRays, queueEntry(queue, i));
#if WP_WORK_ITEMS_ARE_THREADS
  // The path's radiance, added to below, is fetched while the ray is traced: PoCL's connect
  // 7% faster on the shared box, 3% on the instanced scene (where work-items are SIMD lanes,
  // the gathers overlap anyway).
  WP_PREFETCH(WP_BUFFER(pathRadiance)[shadowRayPathSlot(s)]);
#endif
  if (shadowRayUnoccluded(WP_BUFFERS_ARG params, s)) {
    addPathRadiance(WP_BUFFERS_ARG shadowRayPathSlot(s), shadowRayContribution(s));
  }
}

// Accumulate, work item `t` (one per pixel of the pass): adds that pixel's paths' radiance,
// its square (which gives the per-pixel variance) and their feature passes to the pixel's
// running sums (accumulation.h; the feature passes only where the render records them, else
// their layers stay zero), and counts them. It walks the pixel's slots in sample
// order, so there are no races and the sum order is fixed. With adaptive sampling it stops
// the pixel when stopsSampling says so, and adds none of the pixel's later samples (those
// this pass traced anyway are dropped), so a pixel's samples do not depend on the passes.
// Its first work item also empties the queues for the next pass.
WP_FN_INLINED void accumulateStage(WP_BUFFERS RenderParams params, PassConstants pc, uint t) {
  uint pixels = params.pixelCount;
  uint pathCount = pc.pathCount;
  if (t == 0u) {
    finishPassQueues(WP_BUFFERS_ARG params.maxPaths);
  }
  if (t >= min(pathCount, pixels)) {
    return;
  }
  uint pixel = (pc.firstPixel + t) % pixels;
  uint sumAt = accumulationIndex(WP_LAYER_RADIANCE, pixel, pixels);
  uint squaresAt = accumulationIndex(WP_LAYER_RADIANCE_SQUARES, pixel, pixels);
  uint albedoDepthAt = accumulationIndex(WP_LAYER_ALBEDO_DEPTH, pixel, pixels);
  uint normalAt = accumulationIndex(WP_LAYER_NORMAL, pixel, pixels);
  vec4 sum = WP_LOAD(accumulation, sumAt);
  vec4 sumSquares = WP_LOAD(accumulation, squaresAt);
  bool features = recordsFeaturePasses(params);
  vec4 albedoDepth = make_vec4(0.0f, 0.0f, 0.0f, 0.0f);
  vec4 normal = make_vec4(0.0f, 0.0f, 0.0f, 0.0f);
  if (features) {
    albedoDepth = WP_LOAD(accumulation, albedoDepthAt);
    normal = WP_LOAD(accumulation, normalAt);
  }
  float threshold = params.adaptiveThreshold;
  uint minSamples = params.adaptiveMinSamples;
  for (uint slot = t; slot < pathCount && !pixelStopped(sumSquares); slot += pixels) {
    vec3 l = accumulableRadiance(WP_XYZ(WP_LOAD(pathRadiance, slot)));
    WP_ADD_XYZ(sum, l);
    WP_ADD_XYZ(sumSquares, l * l);
    sum = withSampleCounted(sum);
    if (features) {
      PathFeatures f = WP_LOAD(pathFeatures, slot);
      albedoDepth = albedoDepth + f.albedoDepth;
      WP_ADD_XYZ(normal, featureNormal(f));
    }
    if (stopsSampling(sum, sumSquares, threshold, minSamples)) {
      sumSquares = withPixelStopped(sumSquares);
    }
  }
  WP_BUFFER(accumulation)[sumAt] = sum;
  WP_BUFFER(accumulation)[squaresAt] = sumSquares;
  if (features) {
    WP_BUFFER(accumulation)[albedoDepthAt] = albedoDepth;
    WP_BUFFER(accumulation)[normalAt] = normal;
  }
}

WP_END

#endif
