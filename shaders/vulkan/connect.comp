// Stage 5: any-hit test of each shadow ray; unoccluded light samples reach their pixel.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

void main() { connectStage(renderParams(), pc, gl_GlobalInvocationID.x); }
