// Stage 5: any-hit test of each shadow ray; unoccluded light samples reach their pixel.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= counters[WP_COUNTER_SHADOW_RAYS + bounceParity()]) {
    return;
  }
  ShadowRay s = WP_LOAD(shadowRays, i);
  if (shadowRayUnoccluded(params, s)) {
    pathRadiance[pathSlot(s.origin)].xyz += s.contribution.xyz;
  }
}
