// What each wavefront stage computes, apart from reading and writing its buffers: written
// once for the Vulkan (.comp) and OpenCL (.cl) kernels, so both backends trace the same
// paths from the same random numbers and keep their queues the same way.
#ifndef WP_STAGES_H
#define WP_STAGES_H

#include "integrator.h"
#include "layout.h"
#include "rng.h"
#include "thin_lens.h"
#include "traverse.h"

WP_BEGIN

// Workgroups that cover `invocations` invocations.
WP_FN uint dispatchGroups(uint invocations) { return (invocations + WP_WORKGROUP_SIZE - 1u) / WP_WORKGROUP_SIZE; }

// Queue 0 of bounce 0 holds the pass's camera rays (written by generate); every other queue
// and the ray totals start empty. The dispatch words are VkDispatchIndirectCommands.
WP_FN QueueCounters passStartCounters(uint pathCount) {
  QueueCounters c;
  c.counts = make_uvec4(pathCount, 0u, 0u, 0u);
  c.totals = make_uvec4(0u, 0u, 0u, 0u);
  c.extendDispatch = make_uvec4(dispatchGroups(pathCount), 1u, 1u, 0u);
  c.connectDispatch = make_uvec4(0u, 1u, 1u, 0u);
  return c;
}

// After shade of the bounce whose rays are in `queue` (its parity): adds the rays it traced
// and the shadow rays it spawned to the totals, sizes connect (this bounce's shadow rays)
// and the next bounce's extend and shade, and empties the queues their next writers append
// to: the ray queue just consumed, and the shadow queue of the next bounce.
WP_FN QueueCounters advanceCounters(QueueCounters c, uint queue) {
  uint traced = queue == 0u ? c.counts.x : c.counts.y;
  uint nextRays = queue == 0u ? c.counts.y : c.counts.x;
  uint shadows = queue == 0u ? c.counts.z : c.counts.w;
  c.totals.x += traced;
  c.totals.y += shadows;
  c.extendDispatch.x = dispatchGroups(nextRays);
  c.connectDispatch.x = dispatchGroups(shadows);
  c.counts = queue == 0u ? make_uvec4(0u, nextRays, shadows, 0u) : make_uvec4(nextRays, 0u, 0u, shadows);
  return c;
}

// The image pixel (row-major over the whole image) of pixel `regionPixel` of the region
// traced (row-major over the region).
WP_FN uint imagePixel(RenderParams params, uint regionPixel) {
  uint column = params.region.x + regionPixel % params.region.z;
  uint row = params.region.y + regionPixel / params.region.z;
  return row * params.image.x + column;
}

// The camera ray of path slot `slot` of the pass `pc`: slot i is pixel (firstPixel + i) %
// pixels of the region of sample firstSample + (firstPixel + i) / pixels (see
// PassConstants), through a uniformly jittered point of that pixel (a box filter) and a
// point uniform on the lens aperture, at a shutter time uniform in [0, 1), with the path's
// random stream seeded from (image pixel, sample, seed): a pixel's paths are the same
// whichever region or batch of samples traces them.
WP_FN PathRay cameraPathRay(RenderParams params, PassConstants pc, uint slot) {
  uint pixels = params.image.z;
  uint linear = pc.pass.x + slot;
  uint pixel = imagePixel(params, linear % pixels);
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

// Extend: the closest hit of `ray`, as shade reads it.
WP_FN HitRecord extendRay(WP_SCENE_BUFFERS RenderParams params, PathRay ray) {
  Hit h = traceClosest(WP_SCENE_BUFFER_ARGS params.counts.y, params.counts.x, xyz(ray.origin), xyz(ray.direction),
                       WP_FLT_MAX, ray.throughput.w);
  HitRecord record;
  record.hit = make_uvec4(h.instance == WP_INVALID ? WP_INVALID : asUint(h.t), h.instance, h.primitive, 0u);
  return record;
}

// Shade: the vertex `ray` reached (or the sky it left to), from its hit record.
WP_FN ShadeResult shadePath(WP_SHADING_BUFFERS RenderParams params, PathRay ray, uvec4 hit) {
  return hit.x == WP_INVALID ? shadeMiss(WP_SHADING_BUFFER_ARGS params, ray)
                             : shadeHit(WP_SHADING_BUFFER_ARGS params, ray, asFloat(hit.x), hit.y, hit.z);
}

// Connect: whether nothing blocks the shadow ray before its light sample.
WP_FN bool shadowRayUnoccluded(WP_SCENE_BUFFERS RenderParams params, ShadowRay s) {
  return !traceAny(WP_SCENE_BUFFER_ARGS params.counts.y, params.counts.x, xyz(s.origin), xyz(s.direction),
                   s.direction.w, s.contribution.w);
}

WP_END

#endif
