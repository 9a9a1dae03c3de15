// Stage 6: adds each finished path's radiance and its square to its pixel's running sums
// (the squares give the per-pixel variance). One thread per pixel of the pass walks that
// pixel's slots in sample order, so there are no races and the sum order is fixed.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "common/accumulation.h"

void main() {
  uint t = gl_GlobalInvocationID.x;
  uint pixels = params.image.z;
  uint pathCount = pc.pass.z;
  if (t >= min(pathCount, pixels)) {
    return;
  }
  uint pixel = (pc.pass.x + t) % pixels;
  vec4 sum = accumulation[pixel];
  vec4 sumSquares = accumulation[pixels + pixel];
  for (uint slot = t; slot < pathCount; slot += pixels) {
    vec3 l = accumulableRadiance(pathRadiance[slot].xyz);
    sum.xyz += l;
    sumSquares.xyz += l * l;
  }
  accumulation[pixel] = sum;
  accumulation[pixels + pixel] = sumSquares;
}
