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

// Four floats in one SIMD register (GCC's and Clang's vector extension, SSE on x86-64, NEON
// on ARM): binning grows a box's three axes in one instruction instead of three, and maps a
// centroid to its bins on all three at once (wavepath-bench-bvh's 1M triangles: 675-679 ->
// 534-552 ms on one thread, 425-430 -> 339-340 ms on two; the same trees). x, y, z in the
// first three lanes.
typedef float Float4 __attribute__((vector_size(16)));
typedef int32_t Int4 __attribute__((vector_size(16)));

// glm::min and glm::max, lane by lane, with their rule for equal values, so that boxes come
// out bit for bit as Aabb::grow makes them.
Float4 min4(Float4 a, Float4 b) { return b < a ? b : a; }
Float4 max4(Float4 a, Float4 b) { return a < b ? b : a; }
Float4 float4(const glm::vec3& v) { return Float4{v.x, v.y, v.z, 0.0f}; }
glm::vec3 vec3(Float4 v) { return glm::vec3(v[0], v[1], v[2]); }

// Everything binning and partitioning touch, in one 48-byte record, so the build streams
// through one array instead of gathering from three.
struct PrimRef {
  Float4 lo;
  Float4 hi;  // with the primitive's index in the fourth lane's bits, which only max4 sees
  Float4 centroid;
  uint32_t index() const { return std::bit_cast<uint32_t>(hi[3]); }
};

// A bin's bounds; its count is kept apart, so the bounds fill two registers.
struct Bin {
  Float4 lo = Float4{} + std::numeric_limits<float>::max();
  Float4 hi = Float4{} - std::numeric_limits<float>::max();
};

// The area of the box (lo, hi) as boxArea computes it.
float boxArea(Float4 lo, Float4 hi) {
  Float4 e = hi - lo;
  return 2.0f * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
}

Aabb aabb(Float4 lo, Float4 hi) { return Aabb{vec3(lo), vec3(hi)}; }

struct Split {
  bool valid = false;
  uint32_t axis = 0;
  uint32_t lastLeftBin = 0;  // bins 0..lastLeftBin go left
  float cost = 0.0f;         // SAH cost times the node's area (no division: areas may be 0)
  uint32_t leftCount = 0;
  Aabb left, right;
};

// Maps centroids to bins, on all three axes at once; the same mapping bins and partitions, so
// the partition agrees exactly with the counts the split was chosen by.
struct BinMapping {
  Float4 origin;
  Float4 scale;  // 0 on axes without extent: everything falls in bin 0
  uint32_t count;
  // A centroid's bin on each axis. Clamped before the conversion, which is undefined for NaN
  // and for values past int32: below 0 and NaN (an extent of infinity gives 0 * infinity; the
  // loader bounds coordinates, this stays safe) go to bin 0, count and beyond to the last.
  Int4 bins(Float4 centroid) const {
    Float4 x = (centroid - origin) * scale;
    x = x >= 0.0f ? x : Float4{};
    x = x < float(count) ? x : Float4{} + float(count - 1);
    return __builtin_convertvector(x, Int4);
  }
};

class Builder {
public:
  Builder(std::span<const Aabb> bounds, std::span<const glm::vec3> centroids,
          const BvhBuildOptions& options)
      : options_(options), refs_(bounds.size()), nodes_(2 * bounds.size() - 1) {
    for (size_t i = 0; i < bounds.size(); ++i) {
      Float4 hi = float4(bounds[i].max);
      hi[3] = std::bit_cast<float>(static_cast<uint32_t>(i));
      refs_[i] = {float4(bounds[i].min), hi, float4(centroids[i])};
    }
    uint32_t threads = options.threads ? options.threads : std::thread::hardware_concurrency();
    // Two levels beyond one task per thread leave room for uneven splits.
    spawnDepth_ = threads > 1 ? static_cast<uint32_t>(std::bit_width(threads - 1)) + 2 : 0;
  }

  Bvh run() {
    Aabb bounds, centroidBounds;
    for (const PrimRef& r : refs_) {
      bounds.grow(aabb(r.lo, r.hi));
      centroidBounds.grow(vec3(r.centroid));
    }
    nodes_[0].bounds = bounds;
    build(0, 1, 0, static_cast<uint32_t>(refs_.size()), centroidBounds, 0);
    Bvh bvh;
    bvh.nodes = bvh_detail::compactNodes(nodes_);
    bvh.primIndices.resize(refs_.size());
    for (size_t i = 0; i < refs_.size(); ++i) {
      bvh.primIndices[i] = refs_[i].index();
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
        (i < mid ? leftBounds : rightBounds).grow(aabb(refs_[i].lo, refs_[i].hi));
        (i < mid ? leftCentroids : rightCentroids).grow(vec3(refs_[i].centroid));
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
    const BinMapping map = binMapping(centroidBounds, end - begin);
    const uint32_t binCount = map.count;
    std::array<std::array<Bin, kMaxBins>, 3> bins;
    std::array<std::array<uint32_t, kMaxBins>, 3> counts;
    for (uint32_t axis = 0; axis < 3; ++axis) {
      std::fill_n(bins[axis].begin(), binCount, Bin{});
      std::fill_n(counts[axis].begin(), binCount, 0u);
    }
    for (uint32_t i = begin; i < end; ++i) {
      const PrimRef& r = refs_[i];
      const Int4 index = map.bins(r.centroid);
      for (uint32_t axis = 0; axis < 3; ++axis) {
        Bin& b = bins[axis][index[axis]];
        b.lo = min4(b.lo, r.lo);
        b.hi = max4(b.hi, r.hi);
        ++counts[axis][index[axis]];
      }
    }

    const SahCosts& c = options_.costs;
    Split best;
    float bestCost = std::numeric_limits<float>::infinity();
    for (uint32_t axis = 0; axis < 3; ++axis) {
      // Right-to-left sweep: area and count of bins [i, binCount).
      std::array<float, kMaxBins> rightArea;
      std::array<uint32_t, kMaxBins> rightCount;
      Bin acc;
      uint32_t count = 0;
      for (uint32_t i = binCount - 1; i > 0; --i) {
        acc.lo = min4(acc.lo, bins[axis][i].lo);
        acc.hi = max4(acc.hi, bins[axis][i].hi);
        count += counts[axis][i];
        rightArea[i] = count ? boxArea(acc.lo, acc.hi) : 0.0f;
        rightCount[i] = count;
      }
      acc = Bin{};
      count = 0;
      for (uint32_t i = 0; i + 1 < binCount; ++i) {
        acc.lo = min4(acc.lo, bins[axis][i].lo);
        acc.hi = max4(acc.hi, bins[axis][i].hi);
        count += counts[axis][i];
        if (count == 0 || rightCount[i + 1] == 0) {
          continue;
        }
        float cost = c.intersection * (static_cast<float>(count) * boxArea(acc.lo, acc.hi) +
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
      if (counts[best.axis][i]) {
        const Bin& b = bins[best.axis][i];
        (i <= best.lastLeftBin ? best.left : best.right).grow(aabb(b.lo, b.hi));
      }
    }
    return best;
  }

  // Small nodes get fewer bins: sweeping 32 mostly empty bins would cost more than their
  // primitives do.
  static BinMapping binMapping(const Aabb& centroidBounds, uint32_t primCount) {
    BinMapping map{float4(centroidBounds.min), Float4{}, std::clamp(primCount, kMinBins, kMaxBins)};
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
      if (uint32_t(map.bins(refs_[i].centroid)[split.axis]) <= split.lastLeftBin) {
        leftCentroids.grow(vec3(refs_[i].centroid));
        ++i;
      } else {
        --j;
        std::swap(refs_[i], refs_[j]);
        rightCentroids.grow(vec3(refs_[j].centroid));
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
                              (a.centroid[axis] == b.centroid[axis] && a.index() < b.index());
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
