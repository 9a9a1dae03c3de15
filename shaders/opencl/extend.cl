// Stage 2: closest hit of every ray in the current queue.
#include "opencl/bindings.h"
#include "common/stages.h"

WP_KERNEL void extend(WP_KERNEL_ARGS) {
  WP_KERNEL_BUFFERS(buffers)
  extendStage(&buffers, *paramsBuffer, pc, get_global_id(0));
}
