// Stage 2: closest hit of every ray in the current queue.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/traverse.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  uint queue = bounceParity();
  if (i >= counters[WP_COUNTER_RAYS + queue]) {
    return;
  }
  PathRay ray = loadRay(queue * params.counts.w + i);
  Hit h = traceClosest(params.counts.y, params.counts.x, ray.origin.xyz, ray.direction.xyz, WP_FLT_MAX);
  hits[i].hit = uvec4(h.instance == WP_INVALID ? WP_INVALID : floatBitsToUint(h.t), h.instance, h.primitive, 0u);
}
