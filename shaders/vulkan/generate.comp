// Stage 1: one camera ray per path slot of this pass; slot 0 also resets the queues.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

void main() {
  uint slot = gl_GlobalInvocationID.x;
  uint pathCount = pc.pass.z;
  if (slot == 0u) {
    storeCounters(passStartCounters(pathCount));
  }
  if (slot >= pathCount) {
    return;
  }
  rays[slot] = cameraPathRay(params, pc, slot);
  pathRadiance[slot] = vec4(0.0);
}
