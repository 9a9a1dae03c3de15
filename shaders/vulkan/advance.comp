// Stage 4 (one thread): turns this bounce's queue sizes into the indirect dispatch sizes of
// connect and of the next bounce, adds them to the ray totals, and resets the consumed
// queues (advanceQueues in queues.h), all on the GPU so the pass needs no readback.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "bindings.glsl"
#include "common/stages.h"

void main() { advanceStage(renderParams(), pc, gl_GlobalInvocationID.x); }
