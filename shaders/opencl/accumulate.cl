// Stage 6: adds each finished path's radiance and its square to its pixel's running sums
// (the squares give the per-pixel variance). One work item per pixel of the pass walks
// that pixel's slots in sample order, so there are no races and the sum order is fixed.
#include "opencl/bindings.h"
#include "common/accumulation.h"

WP_KERNEL void accumulate(WP_KERNEL_ARGS) {
  uint t = get_global_id(0);
  uint pixels = paramsBuffer->image.z;
  uint pathCount = pc.pass.z;
  if (t >= min(pathCount, pixels)) {
    return;
  }
  uint pixel = (pc.pass.x + t) % pixels;
  float4 sum = accumulation[pixel];
  float4 sumSquares = accumulation[pixels + pixel];
  for (uint slot = t; slot < pathCount; slot += pixels) {
    float3 l = accumulableRadiance(pathRadiance[slot].xyz);
    sum.xyz += l;
    sumSquares.xyz += l * l;
  }
  accumulation[pixel] = sum;
  accumulation[pixels + pixel] = sumSquares;
}
