// Stage 3: shade each hit (shadeStage in stages.h) and append continuations and shadow rays
// to the next queues, which compacts them.
//
// Shade classes: in a scene whose surfaces have both materials that need glTF's BRDF and
// materials that do not (ideal diffuse, unlit: materialShadeNeeds), the backend builds this
// stage twice and runs both in turn. WP_SHADE_CLASS_DIFFUSE, without the BRDF's code, runs
// over the whole ray queue: it shades the misses and its own hits and defers the others to
// the deferred shade queue (queues.h); WP_SHADE_CLASS_MICROFACET, specialized to the whole
// scene, shades those. lavapipe runs every line of a shader for a SIMD group whatever its
// lanes' materials, so a diffuse hit no longer pays for the BRDF (docs/performance.md). The
// results go to each path's own slot: the images are those of one pipeline.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

// This pipeline's shade class, and whether the scene has the other (the diffuse class then
// defers the hits it does not shade).
layout(constant_id = 9) const uint WP_SHADE_CLASS = WP_SHADE_CLASS_DIFFUSE;
layout(constant_id = 10) const bool WP_SHADE_SPLIT = false;

// The entry of `queue` for this invocation, if `wants`. One atomic per subgroup instead of
// one per invocation: atomics serialise lanes, on GPUs and even more on lavapipe, where each
// is a scalar loop over the SIMD lanes.
uint appendToQueue(WorkQueue queue, bool wants) {
  uvec4 ballot = subgroupBallot(wants);
  uint base = 0u;
  if (subgroupElect()) {
    base = reserveQueueEntries(queue, subgroupBallotBitCount(ballot));
  }
  return queueEntry(queue, subgroupBroadcastFirst(base) + subgroupBallotExclusiveBitCount(ballot));
}

// Whether the hit at entry `i` of the bounce's ray queue needs glTF's BRDF.
bool needsMicrofacet(uint i) {
  HitRecord hit = hitsAt(i);
  return !hitIsMiss(hit) &&
         materialShadeNeeds(materialsAt(hitMaterial(hitInstanceField(hit), hitPrimitive(hit)))) != 0u;
}

// Appends entry `i` to the deferred shade queue if `defers`, and raises the queue's
// dispatch to cover it.
void deferShade(uint i, bool defers) {
  uvec4 ballot = subgroupBallot(defers);
  if (ballot == uvec4(0u)) {
    return;
  }
  WorkQueue queue = deferredShadeQueue();
  uint base = 0u;
  if (subgroupElect()) {
    uint count = subgroupBallotBitCount(ballot);
    base = reserveQueueEntries(queue, count);
    atomicMax(counters[WP_COUNTER_DEFERRED_SHADE_DISPATCH], dispatchGroups(base + count));
    counters[WP_COUNTER_DEFERRED_SHADE_DISPATCH + 1u] = 1u;  // every subgroup that appends writes the same
    counters[WP_COUNTER_DEFERRED_SHADE_DISPATCH + 2u] = 1u;
  }
  uint entry = queueEntry(queue, subgroupBroadcastFirst(base) + subgroupBallotExclusiveBitCount(ballot));
  if (defers) {
    deferredHits[entry] = i;
  }
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (WP_SHADE_CLASS == WP_SHADE_CLASS_DIFFUSE) {
    if (i >= queueSize(rayQueue(pc.bounce, params.maxPaths))) {
      return;
    }
    if (WP_SHADE_SPLIT) {
      bool defers = needsMicrofacet(i);
      deferShade(i, defers);
      if (defers) {
        return;
      }
    }
  } else {
    WorkQueue deferred = deferredShadeQueue();
    if (i >= queueSize(deferred)) {
      return;
    }
    i = deferredHitsAt(queueEntry(deferred, i));
  }
  ShadeResult r = shadeStage(params, pc, i);
  bool extends = (r.flags & WP_SHADE_EXTEND) != 0u;
  uint j = appendToQueue(continuationQueue(params, pc), extends);
  if (extends) {
    rays[j] = r.next;
  }
  bool shadows = (r.flags & WP_SHADE_SHADOW) != 0u;
  uint k = appendToQueue(shadowQueue(pc.bounce), shadows);
  if (shadows) {
    shadowRays[k] = r.shadow;
  }
}
