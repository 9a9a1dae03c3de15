// Stage 6: each path's radiance and its square added to its pixel's running sums
// (accumulateStage in stages.h).
#include "opencl/bindings.h"
#include "common/stages.h"

WP_KERNEL void accumulate(WP_KERNEL_ARGS) {
  WP_KERNEL_BUFFERS(buffers)
  accumulateStage(&buffers, *paramsBuffer, pc, get_global_id(0));
}
