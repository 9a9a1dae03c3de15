// Where Vulkan keeps the traversal's stacks (stack_placement.h): in workgroup memory where a
// scene's fit, with room for one more node's children where that fits too; the stages built
// for the last scene kept where they serve the next; the invocations' own arrays otherwise.
#include "backend/vulkan/stack_placement.h"

#include <gtest/gtest.h>

namespace wp::test {
namespace {

// Bytes of workgroup memory that `entries` stack entries per invocation take.
uint64_t bytesOf(uint32_t entries) { return uint64_t(entries) * WP_WORKGROUP_SIZE * sizeof(uint32_t); }

constexpr uint32_t kSpare = WP_BVH_WIDTH - 1;  // one more node's children
constexpr uint64_t kLavapipeBytes = 32768;     // lavapipe's maxComputeSharedMemorySize

TEST(StackPlacement, InWorkgroupMemoryWithRoomForOneMoreNodeWhereItFits) {
  const StackPlacement placed = placeStacks({11, 32}, kLavapipeBytes, StackPlacement{});
  EXPECT_EQ(placed, (StackPlacement{true, 11 + kSpare, 32 + kSpare}));
  EXPECT_EQ(workgroupBytes(placed), bytesOf(11 + 32 + 2 * kSpare));
  EXPECT_EQ(workgroupBytes(StackPlacement{}), 0u);
}

TEST(StackPlacement, ExactWhereOnlyTheNeedsFitAndOwnArraysWhereNotEvenThey) {
  EXPECT_EQ(placeStacks({40, 60}, bytesOf(100), StackPlacement{}), (StackPlacement{true, 40, 60}));
  EXPECT_EQ(placeStacks({40, 61}, bytesOf(100), StackPlacement{}), StackPlacement{});
  // A scene without trees still gets arrays of one entry (GLSL has no empty arrays).
  EXPECT_EQ(placeStacks({0, 0}, kLavapipeBytes, StackPlacement{}), (StackPlacement{true, 1 + kSpare, 1 + kSpare}));
}

TEST(StackPlacement, StagesOfTheLastSceneServeANextThatNeedsNoMore) {
  const StackPlacement first = placeStacks({11, 32}, kLavapipeBytes, StackPlacement{});
  // A new pose whose top level needs a little more or less: the same stages.
  EXPECT_EQ(placeStacks({11 + kSpare, 30}, kLavapipeBytes, first), first);
  EXPECT_EQ(placeStacks({5, 8}, kLavapipeBytes, first), first);
  // One that needs more: new stages, sized to it.
  EXPECT_EQ(placeStacks({15, 32}, kLavapipeBytes, first), (StackPlacement{true, 15 + kSpare, 32 + kSpare}));
  // After stages with their own arrays, a scene that fits goes back to workgroup memory.
  EXPECT_EQ(placeStacks({11, 32}, kLavapipeBytes, StackPlacement{}), first);
}

}  // namespace
}  // namespace wp::test
