// What each wavefront stage computes for one work item, written once for the Vulkan (.comp)
// and OpenCL (.cl) kernels, so both backends trace the same paths from the same random
// numbers and keep their queues (queues.h) the same way. The kernels only add what their
// language does differently: the appends of shade, counted per subgroup or work-group.
#ifndef WP_STAGES_H
#define WP_STAGES_H

#include "binding_table.h"
#include "integrator.h"
#include "queues.h"
#include "rng.h"
#include "thin_lens.h"
#include "traverse.h"

WP_BEGIN

// The camera ray of path slot `slot` of the pass `pc`: slot i is pixel (firstPixel + i) %
// pixels of sample firstSample + (firstPixel + i) / pixels (see PassConstants), through a
// uniformly jittered point of that pixel (a box filter) and a point uniform on the lens
// aperture, at a shutter time uniform in [0, 1), with the path's random stream seeded from
// (pixel, sample, seed).
WP_FN PathRay cameraPathRay(RenderParams params, PassConstants pc, uint slot) {
  uint pixels = params.image.z;
  uint linear = pc.pass.x + slot;
  uint pixel = linear % pixels;
  uint sampleIndex = pc.pass.y + linear / pixels;

  uint rng = rngSeed(pixel, sampleIndex, params.image.w);
  float time = rngTime(rng);
  rng = rngNext(rng);
  float jx = rngFloat(rng);
  rng = rngNext(rng);
  float jy = rngFloat(rng);
  rng = rngNext(rng);
  float lensU = rngFloat(rng);
  rng = rngNext(rng);
  float lensV = rngFloat(rng);
  uint width = params.image.x;
  vec2 film = make_vec2(toFloat(pixel % width) + jx, toFloat(pixel / width) + jy);
  CameraRay camera = sampleThinLensRay(params.camera, film, width, params.image.y, make_vec2(lensU, lensV));

  PathRay ray;
  ray.origin = make_vec4(camera.origin.x, camera.origin.y, camera.origin.z, asFloat(slot));
  ray.direction = make_vec4(camera.direction.x, camera.direction.y, camera.direction.z, 0.0f);
  ray.throughput = make_vec4(1.0f, 1.0f, 1.0f, time);
  ray.state = make_uvec4(rng, 0u, 0u, 0u);
  return ray;
}

// The path slot a ray or shadow ray belongs to (kept in origin.w).
WP_FN uint pathSlot(vec4 origin) { return asUint(origin.w); }

// The closest hit of `ray`, as shade reads it.
WP_FN HitRecord extendRay(WP_BUFFERS RenderParams params, PathRay ray) {
  Hit h = traceClosest(WP_BUFFERS_ARG params.counts.y, params.counts.x, xyz(ray.origin), xyz(ray.direction),
                       WP_FLT_MAX, ray.throughput.w);
  HitRecord record;
  record.hit = make_uvec4(h.instance == WP_INVALID ? WP_INVALID : asUint(h.t), h.instance, h.primitive, 0u);
  return record;
}

// The vertex `ray` reached (or the sky it left to), from its hit record.
WP_FN ShadeResult shadePath(WP_BUFFERS RenderParams params, PathRay ray, uvec4 hit) {
  return hit.x == WP_INVALID ? shadeMiss(WP_BUFFERS_ARG params, ray)
                             : shadeHit(WP_BUFFERS_ARG params, ray, asFloat(hit.x), hit.y, hit.z);
}

// Whether nothing blocks the shadow ray before its light sample.
WP_FN bool shadowRayUnoccluded(WP_BUFFERS RenderParams params, ShadowRay s) {
  return !traceAny(WP_BUFFERS_ARG params.counts.y, params.counts.x, xyz(s.origin), xyz(s.direction),
                   s.direction.w, s.contribution.w);
}

WP_FN void addPathRadiance(WP_BUFFERS uint slot, vec3 radiance) { WP_ADD_XYZ(WP_BUFFER(pathRadiance)[slot], radiance); }

// Generate, work item `slot`: the camera ray of that path slot into bounce 0's ray queue,
// and the path's radiance cleared; the first work item also starts the pass's queues.
WP_FN void generateStage(WP_BUFFERS RenderParams params, PassConstants pc, uint slot) {
  uint pathCount = pc.pass.z;
  uint maxPaths = params.counts.w;
  if (slot == 0u) {
    startPassQueues(WP_BUFFERS_ARG pathCount, maxPaths);
  }
  if (slot >= pathCount) {
    return;
  }
  WP_BUFFER(rays)[queueEntry(rayQueue(0u, maxPaths), slot)] = cameraPathRay(params, pc, slot);
  WP_BUFFER(pathRadiance)[slot] = make_vec4(0.0f, 0.0f, 0.0f, 0.0f);
}

// Extend, work item `i`: the closest hit of entry i of the bounce's ray queue, into hits[i].
WP_FN void extendStage(WP_BUFFERS RenderParams params, PassConstants pc, uint i) {
  WorkQueue queue = rayQueue(pc.pass.w, params.counts.w);
  if (i >= queueSize(WP_BUFFERS_ARG queue)) {
    return;
  }
  WP_BUFFER(hits)[i] = extendRay(WP_BUFFERS_ARG params, WP_LOAD(rays, queueEntry(queue, i)));
}

// Shade, work item `i` (below the size of the bounce's ray queue): the vertex that entry i
// reached, its radiance added to the path. The kernel appends the continuation and the
// shadow ray the result holds to continuationQueue and shadowQueue.
WP_FN ShadeResult shadeStage(WP_BUFFERS RenderParams params, PassConstants pc, uint i) {
  PathRay ray = WP_LOAD(rays, queueEntry(rayQueue(pc.pass.w, params.counts.w), i));
  ShadeResult r = shadePath(WP_BUFFERS_ARG params, ray, WP_LOAD(hits, i).hit);
  if (r.radiance.x != 0.0f || r.radiance.y != 0.0f || r.radiance.z != 0.0f) {
    addPathRadiance(WP_BUFFERS_ARG pathSlot(ray.origin), r.radiance);
  }
  return r;
}

// The queue shade of bounce `pc` appends the paths' continuations to: the next bounce's.
WP_FN WorkQueue continuationQueue(RenderParams params, PassConstants pc) {
  return rayQueue(pc.pass.w + 1u, params.counts.w);
}

// Advance, one work item: the queue sizes of `pc`'s bounce turned into the next stages'
// dispatch arguments (advanceQueues), so the pass needs no readback.
WP_FN void advanceStage(WP_BUFFERS RenderParams params, PassConstants pc, uint i) {
  // The dispatch is one workgroup; a single work item must do the read-modify-writes.
  if (i == 0u) {
    advanceQueues(WP_BUFFERS_ARG pc.pass.w, params.counts.w);
  }
}

// Connect, work item `i`: the shadow ray at entry i of the bounce's shadow queue adds its
// light sample to its path unless something blocks it.
WP_FN void connectStage(WP_BUFFERS RenderParams params, PassConstants pc, uint i) {
  WorkQueue queue = shadowQueue(pc.pass.w);
  if (i >= queueSize(WP_BUFFERS_ARG queue)) {
    return;
  }
  ShadowRay s = WP_LOAD(shadowRays, queueEntry(queue, i));
  if (shadowRayUnoccluded(WP_BUFFERS_ARG params, s)) {
    addPathRadiance(WP_BUFFERS_ARG pathSlot(s.origin), xyz(s.contribution));
  }
}

// Accumulate, work item `t` (one per pixel of the pass): adds that pixel's paths' radiance
// and its square to the pixel's running sums (the squares give the per-pixel variance). It
// walks the pixel's slots in sample order, so there are no races and the sum order is fixed.
WP_FN void accumulateStage(WP_BUFFERS RenderParams params, PassConstants pc, uint t) {
  uint pixels = params.image.z;
  uint pathCount = pc.pass.z;
  if (t >= min(pathCount, pixels)) {
    return;
  }
  uint pixel = (pc.pass.x + t) % pixels;
  vec4 sum = WP_LOAD(accumulation, pixel);
  vec4 sumSquares = WP_LOAD(accumulation, pixels + pixel);
  for (uint slot = t; slot < pathCount; slot += pixels) {
    vec3 l = xyz(WP_LOAD(pathRadiance, slot));
    WP_ADD_XYZ(sum, l);
    WP_ADD_XYZ(sumSquares, l * l);
  }
  WP_BUFFER(accumulation)[pixel] = sum;
  WP_BUFFER(accumulation)[pixels + pixel] = sumSquares;
}

WP_END

#endif
