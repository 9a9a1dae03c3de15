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
  hits[i] = extendRay(WP_SCENE_BUFFER_ARGS params, rays[queue * params.counts.w + i]);
}
