// Stage 2: closest hit of every ray in the current queue.
#include "opencl/bindings.h"
#include "common/stages.h"

WP_KERNEL void extend(WP_KERNEL_ARGS) {
  uint i = get_global_id(0);
  uint queue = bounceParity(pc);
  if (i >= counters[WP_COUNTER_RAYS + queue]) {
    return;
  }
  RenderParams params = *paramsBuffer;
  DeviceBuffers buffers = WP_KERNEL_BUFFERS;
  hits[i] = extendRay(buffers, params, rays[queue * params.counts.w + i]);
}
