// Stage 4 (one work item): turns this bounce's queue sizes into the sizes of connect and of
// the next bounce, adds them to the ray totals and resets the consumed queues
// (advanceQueues in queues.h). The host launches the next stages either at their largest
// size or at the sizes it reads back from here (--cl-dispatch).
#include "opencl/bindings.h"
#include "common/stages.h"

WP_KERNEL void advance(WP_KERNEL_ARGS) {
  WP_KERNEL_BUFFERS(buffers)
  advanceStage(&buffers, *paramsBuffer, pc, get_global_id(0));
}
