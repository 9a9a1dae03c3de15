// Binary BVH over primitive bounding boxes, built with binned SAH; the SAH cost metric.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bvh/aabb.h"

namespace wp {

// Surface area heuristic constants: the cost of one node visit and of one primitive test.
struct SahCosts {
  float traversal = 1.0f;
  float intersection = 1.0f;
};

struct BvhBuildOptions {
  SahCosts costs;
  // A node with more primitives is always split; one with at most this many becomes a leaf
  // when no split is cheaper than the leaf under the SAH.
  uint32_t maxLeafSize = 4;
  // No leaf lies deeper than this (the root has depth 0), so the GPU traversal's fixed stack
  // suffices; nodes that would exceed it are split at the median instead of by the SAH.
  uint32_t maxDepth = 32;
  // Worker threads for the top levels (binned builder only): 0 uses every hardware thread.
  uint32_t threads = 0;
};

// A binary BVH. Interior nodes have two children stored next to each other.
struct Bvh {
  struct Node {
    Aabb bounds;
    uint32_t index = 0;  // interior: left child (the right child is index + 1);
                         // leaf: first entry of its range in primIndices
    uint32_t count = 0;  // primitives in the leaf; 0 for interior nodes
    bool isLeaf() const { return count > 0; }
  };
  std::vector<Node> nodes;           // nodes[0] is the root; empty when there are no primitives
  std::vector<uint32_t> primIndices;  // input primitive indices in leaf order
};

// Builds a BVH with binned SAH (per axis up to 32 bins over the centroid bounds, fewer in
// nodes of fewer primitives). Requires bounds.size() == centroids.size() < 2^31, every box
// non-empty and finite, finite centroids, options.maxLeafSize >= 1 and
// bounds.size() <= maxLeafSize * 2^maxDepth (throws wp::Error otherwise). Deterministic:
// the result does not depend on options.threads.
Bvh buildBvh(std::span<const Aabb> bounds, std::span<const glm::vec3> centroids,
             const BvhBuildOptions& options = {});

// Normalised SAH cost: sum over interior nodes of traversal * A(node) / A(root) plus sum over
// leaves of intersection * count * A(leaf) / A(root). Requires a tree from buildBvh or
// buildBvhSweep; 0 for an empty tree. A root of zero area (all primitives on one line or
// point) gives every node the relative area 1.
float sahCost(const Bvh& bvh, const SahCosts& costs = {});

}  // namespace wp
