// Stage 3: shade each hit (shadeStage in stages.h) and append continuations and shadow rays
// to the next queues, which compacts them.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

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

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= queueSize(rayQueue(pc.bounce, params.maxPaths))) {
    return;
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
