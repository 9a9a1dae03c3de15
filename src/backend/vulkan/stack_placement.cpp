#include "backend/vulkan/stack_placement.h"

#include <algorithm>

#include "shaders/common/layout.h"

namespace wp {

uint64_t workgroupBytes(const StackPlacement& placement) {
  if (!placement.inWorkgroupMemory) return 0;
  return uint64_t(placement.topLevelEntries + placement.bottomLevelEntries) * WP_WORKGROUP_SIZE * sizeof(uint32_t);
}

StackPlacement placeStacks(const TraversalStackNeeds& needs, const StackDevice& device,
                           const StackPlacement& current) {
  if (!device.cpu) return StackPlacement{};
  const StackPlacement exact{true, std::max(needs.topLevel, 1u), std::max(needs.bottomLevel, 1u)};
  if (workgroupBytes(exact) > device.workgroupBytes) return StackPlacement{};
  if (current.inWorkgroupMemory && current.topLevelEntries >= exact.topLevelEntries &&
      current.bottomLevelEntries >= exact.bottomLevelEntries) {
    return current;
  }
  const uint32_t oneMoreNode = WP_BVH_WIDTH - 1;
  const StackPlacement roomy{true, exact.topLevelEntries + oneMoreNode, exact.bottomLevelEntries + oneMoreNode};
  return workgroupBytes(roomy) <= device.workgroupBytes ? roomy : exact;
}

}  // namespace wp
