// Stage 3: shade each hit (shadePath in stages.h) and append continuations and shadow rays
// to the next queues through atomic counters, which compacts them.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

// Slot for this invocation in the queue counted by counters[counter], if `wants`. One
// atomic per subgroup instead of one per invocation: atomics serialise lanes, on GPUs and
// even more on lavapipe, where each is a scalar loop over the SIMD lanes.
uint appendSlot(uint counter, bool wants) {
  uvec4 ballot = subgroupBallot(wants);
  uint base = 0u;
  if (subgroupElect()) {
    base = atomicAdd(counters[counter], subgroupBallotBitCount(ballot));
  }
  return subgroupBroadcastFirst(base) + subgroupBallotExclusiveBitCount(ballot);
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  uint queue = bounceParity();
  if (i >= counters[WP_COUNTER_RAYS + queue]) {
    return;
  }
  uint maxPaths = params.counts.w;
  PathRay ray = WP_LOAD(rays, queue * maxPaths + i);
  ShadeResult r = shadePath(params, ray, WP_LOAD(hits, i).hit);
  uint slot = pathSlot(ray.origin);
  if (r.radiance != vec3(0.0)) {
    pathRadiance[slot].xyz += r.radiance;
  }
  bool extends = (r.flags & WP_SHADE_EXTEND) != 0u;
  uint next = 1u - queue;
  uint j = appendSlot(WP_COUNTER_RAYS + next, extends);
  if (extends) {
    rays[next * maxPaths + j] = r.next;
  }
  bool shadows = (r.flags & WP_SHADE_SHADOW) != 0u;
  uint k = appendSlot(WP_COUNTER_SHADOW_RAYS + queue, shadows);
  if (shadows) {
    shadowRays[k] = r.shadow;
  }
}
