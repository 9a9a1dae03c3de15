// Stage 4 (one thread): turns this bounce's queue counters into the indirect dispatch sizes
// of connect and of the next bounce, adds them to the ray totals, and resets the consumed
// counters, all on the GPU so the pass needs no readback.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"

uint groupsFor(uint n) { return (n + WP_WORKGROUP_SIZE - 1u) / WP_WORKGROUP_SIZE; }

void main() {
  // The dispatch is one workgroup; a single invocation must do the read-modify-writes.
  if (gl_GlobalInvocationID.x != 0u) {
    return;
  }
  uint queue = bounceParity();
  uint traced = counters[WP_COUNTER_RAYS + queue];
  uint nextRays = counters[WP_COUNTER_RAYS + 1u - queue];
  uint shadows = counters[WP_COUNTER_SHADOW_RAYS + queue];
  counters[WP_COUNTER_TOTAL_RAYS] += traced;
  counters[WP_COUNTER_TOTAL_SHADOW_RAYS] += shadows;
  counters[WP_COUNTER_EXTEND_DISPATCH] = groupsFor(nextRays);
  counters[WP_COUNTER_CONNECT_DISPATCH] = groupsFor(shadows);
  counters[WP_COUNTER_RAYS + queue] = 0u;
  counters[WP_COUNTER_SHADOW_RAYS + 1u - queue] = 0u;
}
