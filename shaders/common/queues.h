// The wavefront's work queues, in the spirit of pbrt-v4's WorkQueue: a queue is a run of
// entries in a buffer and its size, a word of the counters buffer (QueueCounters). A stage
// appends by reserving entries with one atomic add on the size, which compacts the queue;
// the next stage runs one work item per entry; the advance stage resets a queue once the
// stage that reads it has run, and writes the dispatch arguments the next stages are sized by.
//
// Two ray queues ping-pong in the rays buffer: the rays of bounce b are queue b & 1, and
// shade of bounce b appends the continuations to the other one, which is bounce b + 1's.
// The shadow queue has one buffer but a size per bounce parity too: advance of bounce b
// must empty the queue shade of bounce b + 1 appends to while connect of bounce b, which
// runs after it, still reads the size of bounce b.
#ifndef WP_QUEUES_H
#define WP_QUEUES_H

#include "binding_table.h"

WP_BEGIN

WP_STRUCT(WorkQueue)
  uint sizeWord;    // the counters word that holds its size (WP_COUNTER_*)
  uint firstEntry;  // its first entry in its buffer
WP_STRUCT_END(WorkQueue)

// The queue that holds the rays of `bounce` (those whose next vertex is that bounce's), in
// the rays buffer of two queues of maxPaths entries.
WP_FN WorkQueue rayQueue(uint bounce, uint maxPaths) {
  WorkQueue q;
  q.sizeWord = WP_COUNTER_RAYS + (bounce & 1u);
  q.firstEntry = (bounce & 1u) * maxPaths;
  return q;
}

// The queue of the shadow rays that shade of `bounce` spawns.
WP_FN WorkQueue shadowQueue(uint bounce) {
  WorkQueue q;
  q.sizeWord = WP_COUNTER_SHADOW_RAYS + (bounce & 1u);
  q.firstEntry = 0u;
  return q;
}

// The queue of the hits that Vulkan's first shade pipeline deferred to the second
// (shade.comp: WP_SHADE_CLASS_MICROFACET), as entries of the bounce's ray queue, in the
// deferredHits buffer.
WP_FN WorkQueue deferredShadeQueue() {
  WorkQueue q;
  q.sizeWord = WP_COUNTER_DEFERRED_SHADES;
  q.firstEntry = 0u;
  return q;
}

// Entry `i` of the queue in its buffer.
WP_FN uint queueEntry(WorkQueue q, uint i) { return q.firstEntry + i; }

WP_FN uint queueSize(WP_BUFFERS WorkQueue q) { return WP_LOAD(counters, q.sizeWord); }

// Reserves `count` entries at the end of the queue, returning the index (from the queue's
// start) of the first one. Callers add up the entries of a subgroup or work-group first:
// atomics serialise, on GPUs and even more on CPU devices.
WP_FN uint reserveQueueEntries(WP_BUFFERS WorkQueue q, uint count) {
  return WP_ATOMIC_ADD(WP_BUFFER(counters)[q.sizeWord], count);
}

WP_FN void resetQueue(WP_BUFFERS WorkQueue q) { WP_BUFFER(counters)[q.sizeWord] = 0u; }

// Workgroups that cover `invocations` invocations.
WP_FN uint dispatchGroups(uint invocations) { return (invocations + WP_WORKGROUP_SIZE - 1u) / WP_WORKGROUP_SIZE; }

// Sets the dispatch arguments at counters word `word` (a VkDispatchIndirectCommand, read by
// OpenCL as a workgroup count) to cover `invocations`.
WP_FN void writeDispatchArguments(WP_BUFFERS uint word, uint invocations) {
  WP_BUFFER(counters)[word] = dispatchGroups(invocations);
  WP_BUFFER(counters)[word + 1u] = 1u;
  WP_BUFFER(counters)[word + 2u] = 1u;
}

// Generate, before the pass's first bounce (the queues are empty: finishPassQueues): the ray
// totals start at zero, extend and shade of bounce 0 are sized to the pass's paths, and
// bounce 0's ray queue holds them, unless `appended`: then generate appends the camera rays
// it traces (adaptive sampling leaves out the pixels that stopped), and the work items of
// extend and shade past the queue's size exit at once.
WP_FN void startPassQueues(WP_BUFFERS uint pathCount, uint maxPaths, bool appended) {
  WP_BUFFER(counters)[WP_COUNTER_TOTAL_RAYS] = 0u;
  WP_BUFFER(counters)[WP_COUNTER_TOTAL_SHADOW_RAYS] = 0u;
  if (!appended) {
    WP_BUFFER(counters)[rayQueue(0u, maxPaths).sizeWord] = pathCount;
  }
  writeDispatchArguments(WP_BUFFERS_ARG WP_COUNTER_EXTEND_DISPATCH, pathCount);
  writeDispatchArguments(WP_BUFFERS_ARG WP_COUNTER_CONNECT_DISPATCH, 0u);
}

// Advance right after generate, when generate appended its camera rays: extend and shade of
// bounce 0 sized to them rather than to every path of the pass (a work item costs even when
// it exits at once: on lavapipe a workgroup of shade takes tens of microseconds).
WP_FN void sizeFirstBounce(WP_BUFFERS uint maxPaths) {
  writeDispatchArguments(WP_BUFFERS_ARG WP_COUNTER_EXTEND_DISPATCH, queueSize(WP_BUFFERS_ARG rayQueue(0u, maxPaths)));
}

// Accumulate, after the pass's last bounce: every queue empty for the next pass's generate,
// which may append to bounce 0's from its first work item on (the backends' configure
// empties them before the first pass). The totals stay for the host to read.
WP_FN void finishPassQueues(WP_BUFFERS uint maxPaths) {
  for (uint parity = 0u; parity < 2u; ++parity) {
    resetQueue(WP_BUFFERS_ARG rayQueue(parity, maxPaths));
    resetQueue(WP_BUFFERS_ARG shadowQueue(parity));
  }
}

// Advance, after shade of `bounce`: adds the rays it traced and the shadow rays it spawned
// to the totals, sizes connect of this bounce and extend and shade of the next, and empties
// the queues their next writers append to: the ray queue just traced (bounce + 2's), the
// shadow queue of bounce + 1 and the deferred shade queue.
WP_FN void advanceQueues(WP_BUFFERS uint bounce, uint maxPaths) {
  uint traced = queueSize(WP_BUFFERS_ARG rayQueue(bounce, maxPaths));
  uint continuing = queueSize(WP_BUFFERS_ARG rayQueue(bounce + 1u, maxPaths));
  uint shadows = queueSize(WP_BUFFERS_ARG shadowQueue(bounce));
  WP_BUFFER(counters)[WP_COUNTER_TOTAL_RAYS] += traced;
  WP_BUFFER(counters)[WP_COUNTER_TOTAL_SHADOW_RAYS] += shadows;
  writeDispatchArguments(WP_BUFFERS_ARG WP_COUNTER_EXTEND_DISPATCH, continuing);
  writeDispatchArguments(WP_BUFFERS_ARG WP_COUNTER_CONNECT_DISPATCH, shadows);
  resetQueue(WP_BUFFERS_ARG rayQueue(bounce, maxPaths));
  resetQueue(WP_BUFFERS_ARG shadowQueue(bounce + 1u));
  // The deferred shade queue too, and its dispatch sized to no workgroups: shade's first
  // pipeline raises x to cover what it appends (atomicMax) and sets y and z to 1 (the
  // counters configure zeroes are as empty).
  resetQueue(WP_BUFFERS_ARG deferredShadeQueue());
  WP_BUFFER(counters)[WP_COUNTER_DEFERRED_SHADE_DISPATCH] = 0u;
}

WP_END

#endif
