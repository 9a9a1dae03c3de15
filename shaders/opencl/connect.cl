// Stage 5: any-hit test of each shadow ray; unoccluded light samples reach their pixel.
#include "opencl/bindings.h"
#include "common/stages.h"

WP_KERNEL void connect(WP_KERNEL_ARGS) {
  uint i = get_global_id(0);
  if (i >= counters[WP_COUNTER_SHADOW_RAYS + bounceParity(pc)]) {
    return;
  }
  ShadowRay s = shadowRays[i];
  DeviceBuffers buffers = WP_KERNEL_BUFFERS;
  if (shadowRayUnoccluded(buffers, *paramsBuffer, s)) {
    pathRadiance[pathSlot(s.origin)].xyz += s.contribution.xyz;
  }
}
