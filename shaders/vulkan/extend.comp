// Stage 2: closest hit of every ray in the current queue.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

void main() { extendStage(renderParams(), pc, gl_GlobalInvocationID.x); }
