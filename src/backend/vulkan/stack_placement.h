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

// Where stages built now keep the stacks of a scene that needs `needs`, on a device with
// `deviceWorkgroupBytes` of workgroup memory (maxComputeSharedMemorySize), given the stages'
// placement `current`: `current` itself where it serves the scene, so that a new pose whose
// top level needs a few entries less builds nothing; else in workgroup memory, with room for
// one more node's children at each level where that fits (an animation's top level is rebuilt
// every pose, a little deeper or shallower); else in the invocations' own arrays, which hold
// any tree.
StackPlacement placeStacks(const TraversalStackNeeds& needs, uint64_t deviceWorkgroupBytes,
                           const StackPlacement& current);

}  // namespace wp
