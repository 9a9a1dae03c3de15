// Stage 1: one camera ray per path slot of this pass; slot 0 also starts the queues.
#include "opencl/bindings.h"
#include "common/stages.h"

WP_KERNEL void generate(WP_KERNEL_ARGS) {
  WP_KERNEL_BUFFERS(buffers)
  generateStage(&buffers, *paramsBuffer, pc, get_global_id(0));
}
