// Binned SAH BVH builder (Wald 2007): up to 32 bins per axis over the centroid bounds, in-place
// partition of compact primitive references, std::thread tasks for the top levels.
#include "bvh/bvh_builder.h"

#include <algorithm>
#include <array>
#include <bit>
#include <thread>

#include "bvh/bvh_tree.h"

namespace wp {
namespace {

constexpr uint32_t kMaxBins = 32;
constexpr uint32_t kMinBins = 4;
// Below this many primitives a subtree is not worth a thread of its own.
constexpr uint32_t kMinParallelPrims = 4096;

// Everything binning and partitioning touch, in one 40-byte record, so the build streams
// through one array instead of gathering from three.
struct PrimRef {
  glm::vec3 centroid;
  uint32_t index;
  glm::vec3 lo;
  glm::vec3 hi;
};

struct Bin {
  glm::vec3 lo{std::numeric_limits<float>::max()};
  uint32_t count = 0;
  glm::vec3 hi{-std::numeric_limits<float>::max()};
};

float boxArea(const glm::vec3& lo, const glm::vec3& hi) {
  glm::vec3 e = hi - lo;
  return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

struct Split {
  bool valid = false;
  uint32_t axis = 0;
  uint32_t lastLeftBin = 0;  // bins 0..lastLeftBin go left
  float cost = 0.0f;         // SAH cost times the node's area (no division: areas may be 0)
  uint32_t leftCount = 0;
  Aabb left, right;
};

// Maps centroids to bins along one axis; the same mapping bins and partitions, so the
// partition agrees exactly with the counts the split was chosen by.
struct BinMapping {
  glm::vec3 origin;
  glm::vec3 scale;  // 0 on axes without extent: everything falls in bin 0
  uint32_t count;
  uint32_t bin(const glm::vec3& c, uint32_t axis) const {
    float x = (c[axis] - origin[axis]) * scale[axis];
    // Compared before the conversion, which is undefined for NaN and for values past uint32
    // (an extent of infinity gives 0 * infinity; the loader bounds coordinates, this stays safe).
    return x >= 0.0f && x < float(count) ? static_cast<uint32_t>(x) : (x >= float(count) ? count - 1 : 0u);
  }
};

class Builder {
public:
  Builder(std::span<const Aabb> bounds, std::span<const glm::vec3> centroids,
          const BvhBuildOptions& options)
      : options_(options), refs_(bounds.size()), nodes_(2 * bounds.size() - 1) {
    for (size_t i = 0; i < bounds.size(); ++i) {
      refs_[i] = {centroids[i], static_cast<uint32_t>(i), bounds[i].min, bounds[i].max};
    }
    uint32_t threads = options.threads ? options.threads : std::thread::hardware_concurrency();
    // Two levels beyond one task per thread leave room for uneven splits.
    spawnDepth_ = threads > 1 ? static_cast<uint32_t>(std::bit_width(threads - 1)) + 2 : 0;
  }

  Bvh run() {
    Aabb bounds, centroidBounds;
    for (const PrimRef& r : refs_) {
      bounds.grow(Aabb{r.lo, r.hi});
      centroidBounds.grow(r.centroid);
    }
    nodes_[0].bounds = bounds;
    build(0, 1, 0, static_cast<uint32_t>(refs_.size()), centroidBounds, 0);
    Bvh bvh;
    bvh.nodes = bvh_detail::compactNodes(nodes_);
    bvh.primIndices.resize(refs_.size());
    for (size_t i = 0; i < refs_.size(); ++i) {
      bvh.primIndices[i] = refs_[i].index;
    }
    return bvh;
  }

private:
  // Builds the subtree of node `nodeIndex` (whose bounds are set) over refs [begin, end);
  // its descendants go from `firstFree` on (see bvh_detail::compactNodes).
  void build(uint32_t nodeIndex, uint32_t firstFree, uint32_t begin, uint32_t end,
             const Aabb& centroidBounds, uint32_t depth) {
    Bvh::Node& node = nodes_[nodeIndex];
    uint32_t n = end - begin;
    bool mustSplit = n > options_.maxLeafSize;
    Split split = n > 1 && depth < options_.maxDepth ? findSplit(begin, end, node.bounds, centroidBounds)
                                                     : Split{};
    float leafCost = options_.costs.intersection * static_cast<float>(n) * node.bounds.area();
    if (!mustSplit && (!split.valid || split.cost >= leafCost)) {
      node.index = begin;
      node.count = n;
      return;
    }

    uint32_t mid;
    Aabb leftCentroids, rightCentroids;
    Aabb leftBounds, rightBounds;
    bool sahFits = split.valid &&
                   depth + 1 + bvh_detail::medianLevels(std::max(split.leftCount, n - split.leftCount),
                                                        options_.maxLeafSize) <=
                       options_.maxDepth;
    if (sahFits) {
      mid = partition(begin, end, split, centroidBounds, leftCentroids, rightCentroids);
      leftBounds = split.left;
      rightBounds = split.right;
    } else {
      // All centroids (nearly) equal, or the SAH split would break the depth budget.
      mid = medianSplit(begin, end, centroidBounds);
      for (uint32_t i = begin; i < end; ++i) {
        (i < mid ? leftBounds : rightBounds).grow(Aabb{refs_[i].lo, refs_[i].hi});
        (i < mid ? leftCentroids : rightCentroids).grow(refs_[i].centroid);
      }
    }

    node.index = firstFree;
    node.count = 0;
    nodes_[firstFree].bounds = leftBounds;
    nodes_[firstFree + 1].bounds = rightBounds;
    uint32_t leftFree = firstFree + 2;
    uint32_t rightFree = leftFree + 2 * (mid - begin) - 2;
    if (depth < spawnDepth_ && n >= kMinParallelPrims) {
      std::thread left([&, leftFree] {
        build(firstFree, leftFree, begin, mid, leftCentroids, depth + 1);
      });
      build(firstFree + 1, rightFree, mid, end, rightCentroids, depth + 1);
      left.join();
    } else {
      build(firstFree, leftFree, begin, mid, leftCentroids, depth + 1);
      build(firstFree + 1, rightFree, mid, end, rightCentroids, depth + 1);
    }
  }

  Split findSplit(uint32_t begin, uint32_t end, const Aabb& bounds, const Aabb& centroidBounds) const {
    BinMapping map = binMapping(centroidBounds, end - begin);
    const uint32_t binCount = map.count;
    std::array<std::array<Bin, kMaxBins>, 3> bins;
    for (auto& axisBins : bins) {
      std::fill_n(axisBins.begin(), binCount, Bin{});
    }
    for (uint32_t i = begin; i < end; ++i) {
      const PrimRef& r = refs_[i];
      for (uint32_t axis = 0; axis < 3; ++axis) {
        Bin& b = bins[axis][map.bin(r.centroid, axis)];
        b.lo = glm::min(b.lo, r.lo);
        b.hi = glm::max(b.hi, r.hi);
        ++b.count;
      }
    }

    const SahCosts& c = options_.costs;
    Split best;
    float bestCost = std::numeric_limits<float>::infinity();
    for (uint32_t axis = 0; axis < 3; ++axis) {
      // Right-to-left sweep: area and count of bins [i, binCount).
      std::array<float, kMaxBins> rightArea;
      std::array<uint32_t, kMaxBins> rightCount;
      Aabb acc;
      uint32_t count = 0;
      for (uint32_t i = binCount - 1; i > 0; --i) {
        acc.grow(Aabb{bins[axis][i].lo, bins[axis][i].hi});
        count += bins[axis][i].count;
        rightArea[i] = count ? boxArea(acc.min, acc.max) : 0.0f;
        rightCount[i] = count;
      }
      acc = Aabb{};
      count = 0;
      for (uint32_t i = 0; i + 1 < binCount; ++i) {
        acc.grow(Aabb{bins[axis][i].lo, bins[axis][i].hi});
        count += bins[axis][i].count;
        if (count == 0 || rightCount[i + 1] == 0) {
          continue;
        }
        float cost = c.intersection * (static_cast<float>(count) * boxArea(acc.min, acc.max) +
                                       static_cast<float>(rightCount[i + 1]) * rightArea[i + 1]);
        if (cost < bestCost) {
          bestCost = cost;
          best.valid = true;
          best.axis = axis;
          best.lastLeftBin = i;
          best.leftCount = count;
        }
      }
    }
    if (!best.valid) {
      return best;
    }
    best.cost = c.traversal * bounds.area() + bestCost;
    for (uint32_t i = 0; i < binCount; ++i) {
      const Bin& b = bins[best.axis][i];
      if (b.count) {
        (i <= best.lastLeftBin ? best.left : best.right).grow(Aabb{b.lo, b.hi});
      }
    }
    return best;
  }

  // Small nodes get fewer bins: sweeping 32 mostly empty bins would cost more than their
  // primitives do.
  static BinMapping binMapping(const Aabb& centroidBounds, uint32_t primCount) {
    BinMapping map{centroidBounds.min, glm::vec3(0.0f), std::clamp(primCount, kMinBins, kMaxBins)};
    glm::vec3 extent = centroidBounds.extent();
    for (int axis = 0; axis < 3; ++axis) {
      float scale = static_cast<float>(map.count) / extent[axis];
      // A tiny extent could make the scale infinite and (c - origin) * scale NaN.
      if (extent[axis] > 0.0f && scale < std::numeric_limits<float>::max()) {
        map.scale[axis] = scale;
      }
    }
    return map;
  }

  uint32_t partition(uint32_t begin, uint32_t end, const Split& split, const Aabb& centroidBounds,
                     Aabb& leftCentroids, Aabb& rightCentroids) {
    BinMapping map = binMapping(centroidBounds, end - begin);
    uint32_t i = begin, j = end;
    while (i < j) {
      if (map.bin(refs_[i].centroid, split.axis) <= split.lastLeftBin) {
        leftCentroids.grow(refs_[i].centroid);
        ++i;
      } else {
        --j;
        std::swap(refs_[i], refs_[j]);
        rightCentroids.grow(refs_[j].centroid);
      }
    }
    return i;
  }

  // Splits at the middle of the range along the longest centroid axis (any order when all
  // centroids are equal).
  uint32_t medianSplit(uint32_t begin, uint32_t end, const Aabb& centroidBounds) {
    glm::vec3 e = centroidBounds.extent();
    int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                     [axis](const PrimRef& a, const PrimRef& b) {
                       return a.centroid[axis] < b.centroid[axis] ||
                              (a.centroid[axis] == b.centroid[axis] && a.index < b.index);
                     });
    return mid;
  }

  const BvhBuildOptions& options_;
  std::vector<PrimRef> refs_;
  std::vector<Bvh::Node> nodes_;  // sparse, see bvh_detail::compactNodes
  uint32_t spawnDepth_ = 0;
};

}  // namespace

Bvh buildBvh(std::span<const Aabb> bounds, std::span<const glm::vec3> centroids,
             const BvhBuildOptions& options) {
  bvh_detail::checkBuildInputs(bounds, centroids, options);
  if (bounds.empty()) {
    return {};
  }
  return Builder(bounds, centroids, options).run();
}

float sahCost(const Bvh& bvh, const SahCosts& costs) {
  if (bvh.nodes.empty()) {
    return 0.0f;
  }
  double rootArea = bvh.nodes[0].bounds.area();
  double sum = 0.0;
  for (const Bvh::Node& node : bvh.nodes) {
    double relativeArea = rootArea > 0.0 ? node.bounds.area() / rootArea : 1.0;
    sum += relativeArea * (node.isLeaf() ? costs.intersection * node.count : costs.traversal);
  }
  return static_cast<float>(sum);
}

}  // namespace wp
