// Reference BVH builder: exact SAH over every split position of the sorted centroids on all
// three axes, keeping the three sorted orders through stable partitions (O(n log n) per level).
#include "bvh/sweep_builder.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

#include "bvh/bvh_tree.h"

namespace wp {
namespace {

class SweepBuilder {
public:
  SweepBuilder(std::span<const Aabb> bounds, std::span<const glm::vec3> centroids,
               const BvhBuildOptions& options)
      : bounds_(bounds), centroids_(centroids), options_(options), nodes_(2 * bounds.size() - 1),
        rightArea_(bounds.size()), goesLeft_(bounds.size()), scratch_(bounds.size()) {
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<uint32_t>& order = order_[axis];
      order.resize(bounds.size());
      std::iota(order.begin(), order.end(), 0u);
      std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return centroids[a][axis] < centroids[b][axis] ||
               (centroids[a][axis] == centroids[b][axis] && a < b);
      });
    }
  }

  Bvh run() {
    uint32_t n = static_cast<uint32_t>(bounds_.size());
    build(0, 1, 0, n, 0);
    Bvh bvh;
    bvh.nodes = bvh_detail::compactNodes(nodes_);
    bvh.primIndices.assign(order_[0].begin(), order_[0].end());
    return bvh;
  }

private:
  // Builds node `nodeIndex` over entries [begin, end) of the three sorted orders, which hold
  // the same primitives; descendants go from `firstFree` on (see bvh_detail::compactNodes).
  void build(uint32_t nodeIndex, uint32_t firstFree, uint32_t begin, uint32_t end, uint32_t depth) {
    Bvh::Node& node = nodes_[nodeIndex];
    uint32_t n = end - begin;
    for (uint32_t i = begin; i < end; ++i) {
      node.bounds.grow(bounds_[order_[0][i]]);
    }
    const SahCosts& c = options_.costs;
    float nodeArea = node.bounds.area();
    float leafCost = c.intersection * static_cast<float>(n) * nodeArea;

    float bestCost = std::numeric_limits<float>::infinity();
    uint32_t bestAxis = 0, bestMid = 0;
    if (n > 1 && depth < options_.maxDepth) {
      for (uint32_t axis = 0; axis < 3; ++axis) {
        const std::vector<uint32_t>& order = order_[axis];
        Aabb acc;
        for (uint32_t i = end - 1; i > begin; --i) {
          acc.grow(bounds_[order[i]]);
          rightArea_[i] = acc.area();
        }
        acc = Aabb{};
        for (uint32_t mid = begin + 1; mid < end; ++mid) {
          acc.grow(bounds_[order[mid - 1]]);
          float cost = c.intersection * (static_cast<float>(mid - begin) * acc.area() +
                                         static_cast<float>(end - mid) * rightArea_[mid]);
          if (cost < bestCost) {
            bestCost = cost;
            bestAxis = axis;
            bestMid = mid;
          }
        }
      }
    }
    bool mustSplit = n > options_.maxLeafSize;
    bool valid = bestCost < std::numeric_limits<float>::infinity();
    if (!mustSplit && (!valid || c.traversal * nodeArea + bestCost >= leafCost)) {
      node.index = begin;
      node.count = n;
      return;
    }
    uint32_t larger = std::max(bestMid - begin, end - bestMid);
    if (!valid ||
        depth + 1 + bvh_detail::medianLevels(larger, options_.maxLeafSize) > options_.maxDepth) {
      // Median of the longest centroid axis keeps the depth budget.
      float longest = -1.0f;
      for (uint32_t axis = 0; axis < 3; ++axis) {
        float extent = centroids_[order_[axis][end - 1]][axis] - centroids_[order_[axis][begin]][axis];
        if (extent > longest) {
          longest = extent;
          bestAxis = axis;
        }
      }
      bestMid = begin + n / 2;
    }

    for (uint32_t i = begin; i < end; ++i) {
      goesLeft_[order_[bestAxis][i]] = i < bestMid;
    }
    for (uint32_t axis = 0; axis < 3; ++axis) {
      if (axis != bestAxis) {
        stablePartition(order_[axis], begin, end);
      }
    }

    node.index = firstFree;
    node.count = 0;
    uint32_t leftFree = firstFree + 2;
    uint32_t rightFree = leftFree + 2 * (bestMid - begin) - 2;
    build(firstFree, leftFree, begin, bestMid, depth + 1);
    build(firstFree + 1, rightFree, bestMid, end, depth + 1);
  }

  // Moves the primitives marked in goesLeft_ to the front of order[begin, end), keeping the
  // sorted order within both sides.
  void stablePartition(std::vector<uint32_t>& order, uint32_t begin, uint32_t end) {
    uint32_t left = begin, right = 0;
    for (uint32_t i = begin; i < end; ++i) {
      uint32_t prim = order[i];
      if (goesLeft_[prim]) {
        order[left++] = prim;
      } else {
        scratch_[right++] = prim;
      }
    }
    std::copy(scratch_.begin(), scratch_.begin() + right, order.begin() + left);
  }

  std::span<const Aabb> bounds_;
  std::span<const glm::vec3> centroids_;
  const BvhBuildOptions& options_;
  std::vector<Bvh::Node> nodes_;  // sparse, see bvh_detail::compactNodes
  std::array<std::vector<uint32_t>, 3> order_;
  std::vector<float> rightArea_;
  std::vector<uint8_t> goesLeft_;
  std::vector<uint32_t> scratch_;
};

}  // namespace

Bvh buildBvhSweep(std::span<const Aabb> bounds, std::span<const glm::vec3> centroids,
                  const BvhBuildOptions& options) {
  bvh_detail::checkBuildInputs(bounds, centroids, options);
  if (bounds.empty()) {
    return {};
  }
  return SweepBuilder(bounds, centroids, options).run();
}

}  // namespace wp
