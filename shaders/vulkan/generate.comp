// Stage 1: one camera ray per path slot of this pass; slot 0 also starts the queues.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

void main() { generateStage(renderParams(), pc, gl_GlobalInvocationID.x); }
