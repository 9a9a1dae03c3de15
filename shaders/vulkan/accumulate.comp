// Stage 6: each path's radiance and its square added to its pixel's running sums
// (accumulateStage in stages.h).
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

void main() { accumulateStage(renderParams(), pc, gl_GlobalInvocationID.x); }
