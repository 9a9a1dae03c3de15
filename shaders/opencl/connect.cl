// Stage 5: any-hit test of each shadow ray; unoccluded light samples reach their pixel.
#include "opencl/bindings.h"
#include "common/stages.h"

WP_KERNEL void connect(WP_KERNEL_ARGS) {
  WP_KERNEL_BUFFERS(buffers)
  connectStage(&buffers, *paramsBuffer, pc, get_global_id(0));
}
