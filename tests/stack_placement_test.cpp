// Where Vulkan keeps the traversal's stacks (stack_placement.h): on a CPU in workgroup memory
// where a scene's fit, with room for one more node's children where that fits too, the stages
// built for the last scene kept where they serve the next; the invocations' own arrays
// otherwise, and always on a GPU.
#include "backend/vulkan/stack_placement.h"

#include <gtest/gtest.h>

namespace wp::test {
namespace {

// Bytes of workgroup memory that `entries` stack entries per invocation take.
uint64_t bytesOf(uint32_t entries) { return uint64_t(entries) * WP_WORKGROUP_SIZE * sizeof(uint32_t); }

constexpr uint32_t kSpare = WP_BVH_WIDTH - 1;  // one more node's children
constexpr StackDevice kLavapipe{32768, true};  // lavapipe's maxComputeSharedMemorySize, a CPU

StackDevice cpuWith(uint64_t workgroupBytes) { return {workgroupBytes, true}; }

TEST(StackPlacement, InWorkgroupMemoryWithRoomForOneMoreNodeWhereItFits) {
  const StackPlacement placed = placeStacks({11, 32}, kLavapipe, StackPlacement{});
  EXPECT_EQ(placed, (StackPlacement{true, 11 + kSpare, 32 + kSpare}));
  EXPECT_EQ(workgroupBytes(placed), bytesOf(11 + 32 + 2 * kSpare));
  EXPECT_EQ(workgroupBytes(StackPlacement{}), 0u);
}

TEST(StackPlacement, ExactWhereOnlyTheNeedsFitAndOwnArraysWhereNotEvenThey) {
  EXPECT_EQ(placeStacks({40, 60}, cpuWith(bytesOf(100)), StackPlacement{}), (StackPlacement{true, 40, 60}));
  EXPECT_EQ(placeStacks({40, 61}, cpuWith(bytesOf(100)), StackPlacement{}), StackPlacement{});
  // A scene without trees still gets arrays of one entry (GLSL has no empty arrays).
  EXPECT_EQ(placeStacks({0, 0}, kLavapipe, StackPlacement{}), (StackPlacement{true, 1 + kSpare, 1 + kSpare}));
}

TEST(StackPlacement, StagesOfTheLastSceneServeANextThatNeedsNoMore) {
  const StackPlacement first = placeStacks({11, 32}, kLavapipe, StackPlacement{});
  // A new pose whose top level needs a little more or less: the same stages.
  EXPECT_EQ(placeStacks({11 + kSpare, 30}, kLavapipe, first), first);
  EXPECT_EQ(placeStacks({5, 8}, kLavapipe, first), first);
  // One that needs more: new stages, sized to it.
  EXPECT_EQ(placeStacks({15, 32}, kLavapipe, first), (StackPlacement{true, 15 + kSpare, 32 + kSpare}));
  // After stages with their own arrays, a scene that fits goes back to workgroup memory.
  EXPECT_EQ(placeStacks({11, 32}, kLavapipe, StackPlacement{}), first);
}

TEST(StackPlacement, OwnArraysOnAGpuWhateverItsWorkgroupMemory) {
  // NVIDIA's 48 KiB would hold the instanced scene's stacks, and cost it 1.8x in traversal.
  const StackDevice gpu{49152, false};
  EXPECT_EQ(placeStacks({11, 32}, gpu, StackPlacement{}), StackPlacement{});
  EXPECT_EQ(placeStacks({1, 8}, gpu, StackPlacement{}), StackPlacement{});
  // Nor are the stages of a CPU's placement kept for it.
  const StackPlacement onCpu = placeStacks({11, 32}, kLavapipe, StackPlacement{});
  EXPECT_EQ(placeStacks({11, 32}, gpu, onCpu), StackPlacement{});
}

}  // namespace
}  // namespace wp::test
