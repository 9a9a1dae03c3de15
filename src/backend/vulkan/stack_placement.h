// Where Vulkan's stages keep the traversal's stacks (traverse.h): in workgroup memory, sized
// to the scene's trees, or in each invocation's own arrays.
#pragma once

#include <cstdint>

#include "bvh/gpu_scene.h"

namespace wp {

// The specialization constants WP_STACKS_IN_WORKGROUP_MEMORY, WP_TOP_LEVEL_STACK_ENTRIES and
// WP_BOTTOM_LEVEL_STACK_ENTRIES (prelude_glsl.h).
struct StackPlacement {
  bool inWorkgroupMemory = false;
  uint32_t topLevelEntries = 1;  // per invocation, in workgroup memory (at least 1: array sizes)
  uint32_t bottomLevelEntries = 1;
  bool operator==(const StackPlacement&) const = default;
};

// Workgroup memory that a placement's stacks take.
uint64_t workgroupBytes(const StackPlacement& placement);

// The device a placement is for: its workgroup memory (maxComputeSharedMemorySize) and
// whether it is a CPU implementation.
struct StackDevice {
  uint64_t workgroupBytes = 0;
  bool cpu = false;
};

// Where stages built now keep the stacks of a scene that needs `needs` on `device`, given the
// stages' placement `current`. On a GPU in the invocations' own arrays, as OpenCL keeps them
// everywhere: a GPU caches them, and workgroup memory taken by stacks bounds the workgroups a
// core runs at once (NVIDIA H200, the instanced scene at 1280x720 and 64 spp: rendered in
// 0.43 s with the stacks in workgroup memory, 0.24 s in own arrays). On a CPU (lavapipe, whose stores to an own array
// run lane by lane: docs/performance.md) in workgroup memory: `current` itself where it serves
// the scene, so that a new pose whose top level needs a few entries less builds nothing; else
// with room for one more node's children at each level where that fits (an animation's top
// level is rebuilt every pose, a little deeper or shallower); else in the invocations' own
// arrays, which hold any tree.
StackPlacement placeStacks(const TraversalStackNeeds& needs, const StackDevice& device,
                           const StackPlacement& current);

}  // namespace wp
