// Animation update benchmark: median per-frame cost of SceneUpdater::update for moving
// instances (top-level rebuild, light table) and for a deforming mesh (refit), with a full
// rebuild of the deforming mesh for comparison.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "bvh/gpu_scene_parts.h"
#include "bvh/scene_update.h"
#include "displaced_sphere.h"

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// What changes on the GPU per frame: nodes, triangle and shading records, instances, lights.
double uploadMiB(const wp::GpuScene& g) {
  size_t bytes = g.nodes.size() * sizeof(g.nodes[0]) + g.triangles.size() * sizeof(g.triangles[0]) +
                 g.triangleShading.size() * sizeof(g.triangleShading[0]) +
                 g.instances.size() * sizeof(g.instances[0]) + g.lights.size() * sizeof(g.lights[0]);
  return static_cast<double>(bytes) / (1024.0 * 1024.0);
}

// Updates `frames` poses and prints the medians of each part.
void run(const char* name, const wp::Scene& first, const std::function<wp::Scene(int)>& pose, int frames,
         float rebuildSahRatio) {
  wp::SceneUpdater updater(first, rebuildSahRatio);
  std::vector<double> tlas, lights, refit, triangles, total;
  uint32_t rebuilds = 0;
  for (int frame = 1; frame <= frames; ++frame) {
    wp::Scene posed = pose(frame);
    updater.update(posed);
    const wp::SceneUpdateTimes& t = updater.times();
    tlas.push_back(t.tlasMs);
    lights.push_back(t.lightsMs);
    refit.push_back(t.refitMs);
    triangles.push_back(t.trianglesMs);
    total.push_back(t.totalMs());
    rebuilds += t.rebuilds;
  }
  const wp::GpuScene& g = updater.scene();
  std::printf("%-34s TLAS %7.2f  lights %7.2f  refit %7.2f  tri records %7.2f  total %7.2f ms"
              "  (%u rebuilds, %zu instances, %zu lights, %.1f MiB)\n",
              name, median(tlas), median(lights), median(refit), median(triangles), median(total), rebuilds,
              g.instances.size(), g.lights.size(), uploadMiB(g));
}

// `count` moving instances of a 100-triangle mesh with two emissive triangles, scattered so
// that they rarely overlap.
void movingInstances(size_t count, int frames) {
  wp::Scene s;
  s.materials.resize(2);
  s.materials[1].emission = glm::vec3(1.0f);
  s.meshes.push_back(wp::bench::displacedSphere(100));
  // Two emitters off the poles, where the triangles are degenerate.
  s.meshes[0].materials[50] = s.meshes[0].materials[51] = 1;
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  float spread = 2.0f * std::cbrt(static_cast<float>(count));
  std::vector<glm::vec3> velocity;
  for (size_t i = 0; i < count; ++i) {
    glm::vec3 p(u(rng), u(rng), u(rng));
    s.instances.push_back({0, glm::translate(glm::mat4(1.0f), spread * p), true});
    velocity.emplace_back(u(rng), u(rng), u(rng));
  }
  auto pose = [&](int frame) {
    wp::Scene posed = s;
    float t = 0.1f * static_cast<float>(frame);
    for (size_t i = 0; i < count; ++i) {
      wp::MeshInstance& inst = posed.instances[i];
      inst.objectToWorld = glm::rotate(glm::translate(inst.objectToWorld, t * velocity[i]), t, velocity[i]);
    }
    return posed;
  };
  char name[64];
  std::snprintf(name, sizeof name, "%zu moving instances", count);
  run(name, s, pose, frames, wp::kRebuildSahRatio);
}

// A deforming mesh of about `triangles` triangles whose bumps travel around it.
void deformingMesh(size_t triangles, int frames) {
  wp::Scene s;
  s.materials.resize(1);
  s.meshes.push_back(wp::bench::displacedSphere(triangles));
  s.meshes[0].deforming = true;
  s.instances.push_back({0, glm::mat4(1.0f)});
  auto pose = [&](int frame) {
    wp::Scene posed = s;
    posed.meshes[0] = wp::bench::displacedSphere(triangles, 0.3f * static_cast<float>(frame));
    posed.meshes[0].deforming = true;
    return posed;
  };
  char name[64];
  std::snprintf(name, sizeof name, "%zu-triangle deforming mesh", s.meshes[0].triangleCount());
  run(name, s, pose, frames, std::numeric_limits<float>::infinity());

  // For comparison: what a rebuild of that mesh costs per frame instead of a refit.
  std::vector<double> build;
  for (int frame = 1; frame <= std::min(frames, 5); ++frame) {
    wp::Scene posed = pose(frame);
    wp::pack_detail::MeshPrimitives prims = wp::pack_detail::meshPrimitives(posed, posed.meshes[0]);
    auto start = Clock::now();
    wp::pack_detail::buildMeshBvh(prims);
    build.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  std::printf("%-34s bottom-level rebuild %7.2f ms (binned SAH, all threads)\n", "", median(build));
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 10;
  size_t triangles = 1'000'000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) {
      frames = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--triangles") && i + 1 < argc) {
      triangles = static_cast<size_t>(std::max(1, std::atoi(argv[++i])));
    } else {
      std::fprintf(stderr, "usage: wavepath-bench-animation [--frames N (10)] [--triangles N (1000000)]\n");
      return 2;
    }
  }
  std::printf("median per-frame SceneUpdater::update over %d frames\n", frames);
  movingInstances(1'000, frames);
  movingInstances(100'000, frames);
  deformingMesh(triangles, frames);
  return 0;
}
