// Stage 3: shade each hit (shadeStage in stages.h) and append continuations and shadow rays
// to the next queues through atomic counters, which compacts them.
//
// Appends are counted per work-group in __local counters, with one global atomic per queue
// and work-group (OpenCL 1.2 has no subgroup ballot). On PoCL this made shade 1.3-1.6x
// faster than an atomic_inc per work item (median of 7 interleaved runs, 256x256, 16 spp),
// as the two cores no longer pass the counters' cache line back and forth per item. The
// barriers need every work item to reach them, so items past the queue length stay.
#include "opencl/bindings.h"
#include "common/stages.h"

WP_KERNEL void shade(WP_KERNEL_ARGS) {
  __local uint rayCount;
  __local uint shadowCount;
  __local uint rayBase;
  __local uint shadowBase;
  uint lid = get_local_id(0);
  if (lid == 0u) {
    rayCount = 0u;
    shadowCount = 0u;
  }
  // Its barrier also orders the counts' reset before the appends.
  WP_KERNEL_BUFFERS(buffers)
  uint i = get_global_id(0);
  RenderParams params = *paramsBuffer;
  WorkQueue continuations = continuationQueue(params, pc);
  WorkQueue shadowRayQueue = shadowQueue(pc.bounce);
  ShadeResult r;
  r.flags = 0u;
  if (i < queueSize(&buffers, rayQueue(pc.bounce, params.maxPaths))) {
    r = shadeStage(&buffers, params, pc, i);
  }
  bool extends = (r.flags & WP_SHADE_EXTEND) != 0u;
  bool shadows = (r.flags & WP_SHADE_SHADOW) != 0u;
  uint j = extends ? atomic_inc(&rayCount) : 0u;
  uint k = shadows ? atomic_inc(&shadowCount) : 0u;
  barrier(CLK_LOCAL_MEM_FENCE);
  if (lid == 0u) {
    rayBase = reserveQueueEntries(&buffers, continuations, rayCount);
    shadowBase = reserveQueueEntries(&buffers, shadowRayQueue, shadowCount);
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  if (extends) {
    rays[queueEntry(continuations, rayBase + j)] = r.next;
  }
  if (shadows) {
    shadowRays[queueEntry(shadowRayQueue, shadowBase + k)] = r.shadow;
  }
}
