// Internals shared by the two BVH builders: input checks, depth budget, node compaction.
#include "bvh/bvh_tree.h"

#include <bit>
#include <cmath>
#include <string>

#include "core/error.h"

namespace wp::bvh_detail {

void checkBuildInputs(std::span<const Aabb> bounds, std::span<const glm::vec3> centroids,
                      const BvhBuildOptions& options) {
  if (bounds.size() != centroids.size()) {
    throw Error("BVH build: " + std::to_string(bounds.size()) + " boxes but " +
                std::to_string(centroids.size()) + " centroids; pass one centroid per box");
  }
  if (bounds.size() >= (size_t{1} << 31)) {
    throw Error("BVH build: " + std::to_string(bounds.size()) +
                " primitives exceed the limit of 2^31; split the mesh");
  }
  if (options.maxLeafSize == 0) {
    throw Error("BVH build: maxLeafSize is 0; it must be at least 1");
  }
  if (!bounds.empty() &&
      medianLevels(static_cast<uint32_t>(bounds.size()), options.maxLeafSize) > options.maxDepth) {
    throw Error("BVH build: " + std::to_string(bounds.size()) + " primitives do not fit in depth " +
                std::to_string(options.maxDepth) + " with leaves of " +
                std::to_string(options.maxLeafSize) + "; raise maxDepth or maxLeafSize");
  }
}

uint32_t medianLevels(uint32_t n, uint32_t maxLeafSize) {
  uint32_t leaves = (n + maxLeafSize - 1) / maxLeafSize;
  return leaves <= 1 ? 0u : static_cast<uint32_t>(std::bit_width(leaves - 1));
}

std::vector<Bvh::Node> compactNodes(const std::vector<Bvh::Node>& sparse) {
  std::vector<Bvh::Node> out;
  if (sparse.empty()) {
    return out;
  }
  out.reserve(sparse.size());
  out.push_back(sparse[0]);
  // Pairs of (old index, new index) of interior nodes whose children are still to be copied.
  std::vector<std::pair<uint32_t, uint32_t>> stack;
  stack.emplace_back(0u, 0u);
  while (!stack.empty()) {
    auto [from, to] = stack.back();
    stack.pop_back();
    if (sparse[from].isLeaf()) {
      continue;
    }
    uint32_t oldChild = sparse[from].index;
    uint32_t newChild = static_cast<uint32_t>(out.size());
    out[to].index = newChild;
    out.push_back(sparse[oldChild]);
    out.push_back(sparse[oldChild + 1]);
    stack.emplace_back(oldChild + 1, newChild + 1);
    stack.emplace_back(oldChild, newChild);
  }
  return out;
}

}  // namespace wp::bvh_detail
