// Stage 1: one camera ray per path slot of this pass; slot 0 also resets the queues.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "common/camera.h"
#include "common/rng.h"

void main() {
  uint slot = gl_GlobalInvocationID.x;
  uint pathCount = pc.pass.z;
  if (slot == 0u) {
    counters[WP_COUNTER_RAYS + 0u] = pathCount;
    counters[WP_COUNTER_RAYS + 1u] = 0u;
    counters[WP_COUNTER_SHADOW_RAYS + 0u] = 0u;
    counters[WP_COUNTER_SHADOW_RAYS + 1u] = 0u;
    counters[WP_COUNTER_TOTAL_RAYS] = 0u;
    counters[WP_COUNTER_TOTAL_SHADOW_RAYS] = 0u;
    counters[WP_COUNTER_EXTEND_DISPATCH + 0u] = (pathCount + WP_WORKGROUP_SIZE - 1u) / WP_WORKGROUP_SIZE;
    counters[WP_COUNTER_EXTEND_DISPATCH + 1u] = 1u;
    counters[WP_COUNTER_EXTEND_DISPATCH + 2u] = 1u;
    counters[WP_COUNTER_CONNECT_DISPATCH + 0u] = 0u;
    counters[WP_COUNTER_CONNECT_DISPATCH + 1u] = 1u;
    counters[WP_COUNTER_CONNECT_DISPATCH + 2u] = 1u;
  }
  if (slot >= pathCount) {
    return;
  }
  uint pixels = params.image.z;
  uint linear = pc.pass.x + slot;
  uint pixel = linear % pixels;
  uint sampleIndex = pc.pass.y + linear / pixels;

  uint rng = rngSeed(pixel, sampleIndex, params.image.w);
  rng = rngNext(rng);
  float jx = rngFloat(rng);
  rng = rngNext(rng);
  float jy = rngFloat(rng);
  uint width = params.image.x;
  vec2 film = vec2(float(pixel % width) + jx, float(pixel / width) + jy);
  vec3 dir = cameraRayDirection(params.cameraForward.xyz, params.cameraRight.xyz, params.cameraUp.xyz, film, width,
                                params.image.y);

  PathRay ray;
  ray.origin = vec4(params.cameraPosition.xyz, uintBitsToFloat(slot));
  ray.direction = vec4(dir, 0.0);
  ray.throughput = vec4(1.0);
  ray.state = uvec4(rng, 0u, 0u, 0u);
  rays[slot] = ray;
  pathRadiance[slot] = vec4(0.0);
}
