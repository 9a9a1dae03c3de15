// Stage 1: one camera ray per path slot of this pass; slot 0 also resets the queues.
#include "opencl/bindings.h"
#include "common/stages.h"

WP_KERNEL void generate(WP_KERNEL_ARGS) {
  uint slot = get_global_id(0);
  uint pathCount = pc.pass.z;
  if (slot == 0u) {
    storeCounters(counters, passStartCounters(pathCount));
  }
  if (slot >= pathCount) {
    return;
  }
  rays[slot] = cameraPathRay(*paramsBuffer, pc, slot);
  pathRadiance[slot] = (float4)(0.0f);
}
