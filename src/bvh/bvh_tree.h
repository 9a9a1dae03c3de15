// Internals shared by the two BVH builders: input checks, depth budget, node compaction.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bvh/bvh_builder.h"

namespace wp::bvh_detail {

// Throws wp::Error unless the inputs meet buildBvh's stated requirements.
void checkBuildInputs(std::span<const Aabb> bounds, std::span<const glm::vec3> centroids,
                      const BvhBuildOptions& options);

// Levels below a node of n primitives that median splits need before every leaf holds at
// most maxLeafSize primitives. Requires maxLeafSize >= 1.
uint32_t medianLevels(uint32_t n, uint32_t maxLeafSize);

// Builders write the two children of a node with n primitives at `firstFree` and the
// descendants of the left child from firstFree + 2, of the right one from
// firstFree + 2 * nLeft: each subtree owns a fixed slice of a 2n - 1 node array, so subtrees
// can be built in parallel and the result does not depend on scheduling. This returns the
// tree with the gaps removed, nodes in depth-first order. Requires nodes[0] to be the root.
std::vector<Bvh::Node> compactNodes(const std::vector<Bvh::Node>& sparse);

}  // namespace wp::bvh_detail
