// Refit of a built BVH to moved primitives: one reverse sweep over the depth-first node order.
#include "bvh/bvh_refit.h"

#include <string>

#include "core/error.h"

namespace wp {

void refitBvh(Bvh& bvh, std::span<const Aabb> primBounds) {
  if (bvh.primIndices.size() != primBounds.size()) {
    throw Error("BVH refit: the tree holds " + std::to_string(bvh.primIndices.size()) + " primitives but " +
                std::to_string(primBounds.size()) + " boxes were given; refit with the same primitives");
  }
  // Children come after their parents, so a reverse sweep sees both children of a node
  // before the node itself.
  for (size_t i = bvh.nodes.size(); i-- > 0;) {
    Bvh::Node& node = bvh.nodes[i];
    Aabb bounds;
    if (node.isLeaf()) {
      for (uint32_t p = node.index; p < node.index + node.count; ++p) {
        bounds.grow(primBounds[bvh.primIndices[p]]);
      }
    } else {
      if (node.index <= i || node.index + 1 >= bvh.nodes.size()) {
        throw Error("BVH refit: node " + std::to_string(i) +
                    " does not store its children after itself; refit trees from buildBvh");
      }
      bounds = bvh.nodes[node.index].bounds;
      bounds.grow(bvh.nodes[node.index + 1].bounds);
    }
    node.bounds = bounds;
  }
}

}  // namespace wp
