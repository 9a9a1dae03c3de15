// The GPU's 4-wide BVH nodes (layout.h's BvhNode), collapsed from a binary BVH.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "bvh/bvh_builder.h"
#include "shaders/common/layout.h"

namespace wp {

// The shape of a 4-wide tree over a binary BVH: which binary nodes each wide node holds as
// children. Kept with a deforming mesh so a refit writes new bounds into the same wide tree.
struct WideLayout {
  struct Node {
    std::array<uint32_t, WP_BVH_WIDTH> children{};  // binary node indices, in slot order
    std::array<uint32_t, WP_BVH_WIDTH> wide{};      // an interior child's wide node position; WP_INVALID for leaves
    uint32_t count = 0;                              // slots used
  };
  std::vector<Node> nodes;  // in GPU order; nodes[0] is the root
};

// Collapses `bvh` to 4 wide: each node takes a binary node's two children and keeps opening
// the child of largest surface area (the one a ray most likely enters) until it holds four or
// only leaves are left, as Embree collapses its builds; the children of a node lie next to
// each other, after their parent. An empty tree or a single leaf gives one node. Requires a
// tree from buildBvh or buildBvhSweep whose leaves hold fewer than 8 primitives (the
// traversal packs the count in 3 bits, traverse.h); throws wp::Error otherwise.
WideLayout collapseToWide(const Bvh& bvh);

// The GPU nodes of `layout` with the bounds of `bvh` (the tree it was collapsed from, or that
// tree refitted), as they lie at out[base...]: leaf ranges offset by primBase, interior child
// indices absolute.
std::vector<gpu::BvhNode> wideNodes(const Bvh& bvh, const WideLayout& layout, uint32_t primBase, uint32_t base);

// wideNodes placed at the end of `out`; returns where its root now lies.
uint32_t appendWideNodes(const Bvh& bvh, const WideLayout& layout, uint32_t primBase, std::vector<gpu::BvhNode>& out);

// The most entries traverse.h's stack holds at once while a ray walks the tree whose root is
// nodes[root] (either level): at every node on the way down, the children the ray reaches but
// the nearest wait on the stack, so the most that any path from the root leaves there (each
// node's used slots but one), and one more for the leaf that a bottom-level lane already
// holding one pushes back. At most (WP_BVH_WIDTH - 1) * WP_BVH_MAX_DEPTH + 1.
uint32_t traversalStackEntries(const std::vector<gpu::BvhNode>& nodes, uint32_t root);

// A node whose four slots are empty.
gpu::BvhNode emptyWideNode();

// Slot `slot` (0 to 3) of `node`: the child's bounds, then a node index with count 0 or a
// leaf's first primitive and count.
void setWideChild(gpu::BvhNode& node, uint32_t slot, const Aabb& bounds, uint32_t index, uint32_t count);

}  // namespace wp
