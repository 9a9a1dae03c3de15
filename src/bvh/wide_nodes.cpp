// Collapse of a binary BVH into the GPU's 4-wide nodes. Four children per node halve the
// iterations of the traversal loop, which on lavapipe each SIMD group pays in full, and let
// PoCL test the four boxes with one vec4 instruction per step (docs/performance.md).
#include "bvh/wide_nodes.h"

#include <algorithm>
#include <array>
#include <string>

#include "core/error.h"
#include "shaders/common/traverse.h"

namespace wp {

gpu::BvhNode emptyWideNode() {
  gpu::BvhNode node{};
  node.childIndex = glm::uvec4(WP_INVALID);
  node.childCount = glm::uvec4(0u);
  return node;
}

void setWideChild(gpu::BvhNode& node, uint32_t slot, const Aabb& bounds, uint32_t index, uint32_t count) {
  node.childMinX[slot] = bounds.min.x;
  node.childMaxX[slot] = bounds.max.x;
  node.childMinY[slot] = bounds.min.y;
  node.childMaxY[slot] = bounds.max.y;
  node.childMinZ[slot] = bounds.min.z;
  node.childMaxZ[slot] = bounds.max.z;
  node.childIndex[slot] = index;
  node.childCount[slot] = count;
}

namespace {

constexpr uint32_t kWidth = WP_BVH_WIDTH;

// The binary nodes that become the children of the wide node standing for interior node
// `parent`: its two children, each interior one of largest area opened in place (so the
// children stay in the builder's spatial order) while there is room.
std::array<uint32_t, kWidth> collapsedChildren(const Bvh& bvh, uint32_t parent, uint32_t& count) {
  std::array<uint32_t, kWidth> children{bvh.nodes[parent].index, bvh.nodes[parent].index + 1};
  count = 2;
  while (count < kWidth) {
    uint32_t widest = kWidth;
    float widestArea = -1.0f;
    for (uint32_t k = 0; k < count; ++k) {
      const Bvh::Node& child = bvh.nodes[children[k]];
      if (!child.isLeaf() && child.bounds.area() > widestArea) {
        widest = k;
        widestArea = child.bounds.area();
      }
    }
    if (widest == kWidth) {
      break;
    }
    uint32_t opened = bvh.nodes[children[widest]].index;
    for (uint32_t k = count; k > widest + 1; --k) {
      children[k] = children[k - 1];
    }
    children[widest] = opened;
    children[widest + 1] = opened + 1;
    ++count;
  }
  return children;
}

void checkLeaf(const Bvh::Node& leaf) {
  if (leaf.count >= (1u << (32 - WP_ENTRY_COUNT_SHIFT))) {
    throw Error("BVH packing: a leaf holds " + std::to_string(leaf.count) +
                " primitives, more than the traversal's stack entries can count; build with smaller leaves");
  }
}

}  // namespace

WideLayout collapseToWide(const Bvh& bvh) {
  WideLayout layout;
  layout.nodes.emplace_back();
  if (bvh.nodes.empty()) {
    return layout;
  }
  if (bvh.nodes[0].isLeaf()) {
    checkLeaf(bvh.nodes[0]);
    layout.nodes[0].children[0] = 0;
    layout.nodes[0].wide[0] = WP_INVALID;
    layout.nodes[0].count = 1;
    return layout;
  }
  struct Pending {
    uint32_t binary;  // an interior node of bvh
    uint32_t wide;    // the position of its wide node
  };
  std::vector<Pending> pending{{0, 0}};
  while (!pending.empty()) {
    Pending p = pending.back();
    pending.pop_back();
    WideLayout::Node node;
    node.children = collapsedChildren(bvh, p.binary, node.count);
    for (uint32_t k = 0; k < node.count; ++k) {
      const Bvh::Node& child = bvh.nodes[node.children[k]];
      node.wide[k] = WP_INVALID;
      if (child.isLeaf()) {
        checkLeaf(child);
      } else {
        node.wide[k] = static_cast<uint32_t>(layout.nodes.size());
        layout.nodes.emplace_back();
        pending.push_back({node.children[k], node.wide[k]});
      }
    }
    layout.nodes[p.wide] = node;
  }
  return layout;
}

std::vector<gpu::BvhNode> wideNodes(const Bvh& bvh, const WideLayout& layout, uint32_t primBase, uint32_t base) {
  std::vector<gpu::BvhNode> out(layout.nodes.size(), emptyWideNode());
  for (size_t i = 0; i < layout.nodes.size(); ++i) {
    const WideLayout::Node& node = layout.nodes[i];
    for (uint32_t k = 0; k < node.count; ++k) {
      const Bvh::Node& child = bvh.nodes[node.children[k]];
      if (node.wide[k] == WP_INVALID) {
        setWideChild(out[i], k, child.bounds, primBase + child.index, child.count);
      } else {
        setWideChild(out[i], k, child.bounds, base + node.wide[k], 0);
      }
    }
  }
  return out;
}

uint32_t appendWideNodes(const Bvh& bvh, const WideLayout& layout, uint32_t primBase, std::vector<gpu::BvhNode>& out) {
  const uint32_t root = static_cast<uint32_t>(out.size());
  std::vector<gpu::BvhNode> nodes = wideNodes(bvh, layout, primBase, root);
  out.insert(out.end(), nodes.begin(), nodes.end());
  return root;
}

uint32_t traversalStackEntries(const std::vector<gpu::BvhNode>& nodes, uint32_t root) {
  struct Visit {
    uint32_t node;
    uint32_t below;  // entries the nodes above it leave on the stack
  };
  std::vector<Visit> pending{{root, 0}};
  uint32_t most = 0;
  while (!pending.empty()) {
    const Visit visit = pending.back();
    pending.pop_back();
    const gpu::BvhNode& node = nodes.at(visit.node);
    uint32_t used = 0;
    for (uint32_t k = 0; k < kWidth; ++k) used += node.childIndex[k] != WP_INVALID;
    const uint32_t waiting = visit.below + (used > 0 ? used - 1 : 0);
    most = std::max(most, waiting);
    for (uint32_t k = 0; k < kWidth; ++k) {
      if (node.childIndex[k] != WP_INVALID && node.childCount[k] == 0) pending.push_back({node.childIndex[k], waiting});
    }
  }
  return most + 1;
}

}  // namespace wp
