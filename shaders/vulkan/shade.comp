// Stage 3: shade each hit (integrator.h) and append continuations and shadow rays to the
// next queues through atomic counters, which compacts them.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "common/integrator.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  uint queue = bounceParity();
  if (i >= counters[WP_COUNTER_RAYS + queue]) {
    return;
  }
  uint maxPaths = params.counts.w;
  PathRay ray = rays[queue * maxPaths + i];
  uvec4 h = hits[i].hit;
  ShadeResult r = h.x == WP_INVALID ? shadeMiss(params, ray)
                                    : shadeHit(params, ray, uintBitsToFloat(h.x), h.y, h.z);
  uint slot = floatBitsToUint(ray.origin.w);
  pathRadiance[slot].xyz += r.radiance;
  if ((r.flags & WP_SHADE_EXTEND) != 0u) {
    uint next = 1u - queue;
    uint j = atomicAdd(counters[WP_COUNTER_RAYS + next], 1u);
    rays[next * maxPaths + j] = r.next;
  }
  if ((r.flags & WP_SHADE_SHADOW) != 0u) {
    uint j = atomicAdd(counters[WP_COUNTER_SHADOW_RAYS + queue], 1u);
    shadowRays[j] = r.shadow;
  }
}
