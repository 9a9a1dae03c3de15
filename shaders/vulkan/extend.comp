// Stage 2: closest hit of every ray in the current queue.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  uint queue = bounceParity();
  if (i >= counters[WP_COUNTER_RAYS + queue]) {
    return;
  }
  hits[i] = extendRay(params, WP_LOAD(rays, queue * params.counts.w + i));
}
