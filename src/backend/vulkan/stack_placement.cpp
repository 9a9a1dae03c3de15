#include "backend/vulkan/stack_placement.h"

#include <algorithm>

#include "shaders/common/layout.h"

namespace wp {

uint64_t workgroupBytes(const StackPlacement& placement) {
  if (!placement.inWorkgroupMemory) return 0;
  return uint64_t(placement.topLevelEntries + placement.bottomLevelEntries) * WP_WORKGROUP_SIZE * sizeof(uint32_t);
}

StackPlacement placeStacks(const TraversalStackNeeds& needs, uint64_t deviceWorkgroupBytes,
                           const StackPlacement& current) {
  const StackPlacement exact{true, std::max(needs.topLevel, 1u), std::max(needs.bottomLevel, 1u)};
  if (workgroupBytes(exact) > deviceWorkgroupBytes) return StackPlacement{};
  if (current.inWorkgroupMemory && current.topLevelEntries >= exact.topLevelEntries &&
      current.bottomLevelEntries >= exact.bottomLevelEntries) {
    return current;
  }
  const uint32_t oneMoreNode = WP_BVH_WIDTH - 1;
  const StackPlacement roomy{true, exact.topLevelEntries + oneMoreNode, exact.bottomLevelEntries + oneMoreNode};
  return workgroupBytes(roomy) <= deviceWorkgroupBytes ? roomy : exact;
}

}  // namespace wp
