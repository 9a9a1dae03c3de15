// Stage 5: any-hit test of each shadow ray; unoccluded light samples reach their pixel.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/traverse.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= counters[WP_COUNTER_SHADOW_RAYS + bounceParity()]) {
    return;
  }
  ShadowRay s = loadShadowRay(i);
  if (!traceAny(params.counts.y, params.counts.x, s.origin.xyz, s.direction.xyz, s.direction.w)) {
    pathRadiance[floatBitsToUint(s.origin.w)].xyz += s.contribution.xyz;
  }
}
