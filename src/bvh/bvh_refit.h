// Refit of a built BVH to moved primitives: bounds recomputed bottom-up, topology kept.
#pragma once

#include <span>

#include "bvh/bvh_builder.h"

namespace wp {

// Recomputes every node's bounds for new primitive bounds: leaves from their primitives,
// interior nodes from their children. Cheaper than a build, but the tree keeps the grouping
// chosen for the old positions, so its SAH cost grows as the primitives move apart (compare
// sahCost with that of a fresh build to decide when to rebuild). Requires `bvh` from
// buildBvh or buildBvhSweep over primBounds.size() primitives (children stored after their
// parents, as bvh_detail::compactNodes leaves them); throws wp::Error otherwise.
void refitBvh(Bvh& bvh, std::span<const Aabb> primBounds);

}  // namespace wp
