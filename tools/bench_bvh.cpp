// BVH build benchmark: median binned SAH build time and quality on a 1M-triangle displaced
// sphere; with --sweep also the exhaustive sweep builder on a smaller one for comparison.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bvh/bvh_builder.h"
#include "bvh/sweep_builder.h"

namespace {

struct Primitives {
  std::vector<wp::Aabb> bounds;
  std::vector<glm::vec3> centroids;
};

// A UV sphere of about `triangles` triangles whose radius is displaced by a few octaves of
// sines, so the surface is bumpy at several scales, like a scanned model (deterministic).
Primitives displacedSphere(size_t triangles) {
  int rings = std::max(2, static_cast<int>(std::sqrt(static_cast<double>(triangles) / 4.0)));
  int segments = 2 * rings;
  auto vertex = [&](int ring, int segment) {
    float theta = 3.14159265f * static_cast<float>(ring) / static_cast<float>(rings);
    float phi = 6.28318531f * static_cast<float>(segment) / static_cast<float>(segments);
    glm::vec3 dir(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    float r = 1.0f + 0.1f * std::sin(7.0f * dir.x) * std::sin(5.0f * dir.y + 1.0f) +
              0.03f * std::sin(31.0f * dir.z + 2.0f * dir.x) + 0.01f * std::sin(97.0f * dir.y);
    return r * dir;
  };
  Primitives p;
  auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    wp::Aabb box;
    box.grow(a);
    box.grow(b);
    box.grow(c);
    p.bounds.push_back(box);
    p.centroids.push_back((a + b + c) * (1.0f / 3.0f));
  };
  for (int ring = 0; ring < rings; ++ring) {
    for (int segment = 0; segment < segments; ++segment) {
      glm::vec3 a = vertex(ring, segment), b = vertex(ring, segment + 1);
      glm::vec3 c = vertex(ring + 1, segment), d = vertex(ring + 1, segment + 1);
      add(a, c, b);
      add(b, c, d);
    }
  }
  return p;
}

using BuildFn = wp::Bvh (*)(std::span<const wp::Aabb>, std::span<const glm::vec3>,
                            const wp::BvhBuildOptions&);

struct Result {
  double medianMs;
  wp::Bvh bvh;
};

Result measure(BuildFn build, const Primitives& p, const wp::BvhBuildOptions& options, int runs) {
  std::vector<double> ms;
  wp::Bvh bvh;
  for (int i = 0; i < runs; ++i) {
    auto start = std::chrono::steady_clock::now();
    bvh = build(p.bounds, p.centroids, options);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  return {ms[ms.size() / 2], std::move(bvh)};
}

void report(const char* name, size_t triangles, const Result& r) {
  std::printf("%-28s %9zu tris  median %9.1f ms  %7.2f Mtris/s  SAH %8.3f  nodes %zu\n", name,
              triangles, r.medianMs, static_cast<double>(triangles) / r.medianMs / 1e3,
              static_cast<double>(wp::sahCost(r.bvh)), r.bvh.nodes.size());
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  bool sweep = false;
  size_t triangles = 1'000'000;
  size_t sweepTriangles = 100'000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sweep")) {
      sweep = true;
    } else if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--triangles") && i + 1 < argc) {
      triangles = static_cast<size_t>(std::max(1, std::atoi(argv[++i])));
    } else {
      std::fprintf(stderr,
                   "usage: wavepath-bench-bvh [--runs N (5)] [--triangles N (1000000)] [--sweep]\n");
      return 2;
    }
  }

  Primitives big = displacedSphere(triangles);
  wp::BvhBuildOptions single;
  single.threads = 1;
  wp::BvhBuildOptions parallel;  // every hardware thread
  std::printf("binned SAH, up to 32 bins, leaves <= %u, costs traversal %.1f intersection %.1f, %d runs\n",
              single.maxLeafSize, single.costs.traversal, single.costs.intersection, runs);
  report("binned, 1 thread", big.bounds.size(), measure(wp::buildBvh, big, single, runs));
  report("binned, all threads", big.bounds.size(), measure(wp::buildBvh, big, parallel, runs));

  if (sweep) {
    Primitives small = displacedSphere(sweepTriangles);
    Result binned = measure(wp::buildBvh, small, single, runs);
    Result full = measure(wp::buildBvhSweep, small, single, 1);
    report("binned, 1 thread", small.bounds.size(), binned);
    report("full sweep", small.bounds.size(), full);
    std::printf("SAH binned / sweep: %.4f\n",
                static_cast<double>(wp::sahCost(binned.bvh) / wp::sahCost(full.bvh)));
  }
  return 0;
}
