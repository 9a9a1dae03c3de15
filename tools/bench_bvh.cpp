// BVH build benchmark: median binned SAH build time and quality on a 1M-triangle displaced
// sphere; with --sweep also the exhaustive sweep builder on a smaller one for comparison.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bvh/bvh_builder.h"
#include "bvh/gpu_scene_parts.h"
#include "bvh/sweep_builder.h"
#include "displaced_sphere.h"

namespace {

using Primitives = wp::pack_detail::MeshPrimitives;

Primitives primitivesOf(const wp::Mesh& mesh) {
  wp::Scene scene;
  scene.materials.resize(1);
  return wp::pack_detail::meshPrimitives(scene, mesh);
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

  Primitives big = primitivesOf(wp::bench::displacedSphere(triangles));
  wp::BvhBuildOptions single;
  single.threads = 1;
  wp::BvhBuildOptions parallel;  // every hardware thread
  std::printf("binned SAH, up to 32 bins, leaves <= %u, costs traversal %.1f intersection %.1f, %d runs\n",
              single.maxLeafSize, single.costs.traversal, single.costs.intersection, runs);
  report("binned, 1 thread", big.bounds.size(), measure(wp::buildBvh, big, single, runs));
  report("binned, all threads", big.bounds.size(), measure(wp::buildBvh, big, parallel, runs));

  if (sweep) {
    Primitives small = primitivesOf(wp::bench::displacedSphere(sweepTriangles));
    Result binned = measure(wp::buildBvh, small, single, runs);
    Result full = measure(wp::buildBvhSweep, small, single, 1);
    report("binned, 1 thread", small.bounds.size(), binned);
    report("full sweep", small.bounds.size(), full);
    std::printf("SAH binned / sweep: %.4f\n",
                static_cast<double>(wp::sahCost(binned.bvh) / wp::sahCost(full.bvh)));
  }
  return 0;
}
