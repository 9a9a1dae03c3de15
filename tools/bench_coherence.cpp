// Ray-order benchmark, to decide whether the wavefront should sort its rays before traversal:
// traces a scene's camera rays (one per pixel, in the stages' row-major order), then one
// cosine-distributed bounce ray from each surface they hit, on one CPU thread with the
// traversal the stages run (shaders/common/traverse.h), in three orders: as shade appends
// them (the order of the pixels they leave from), sorted by a key (direction octant, then
// the Morton code of the origin in the scene's bounds), and shuffled. Every order traces the
// same rays and must find the same hits (checked). Prints Mrays/s per order, medians of runs.
// Measuring only: never part of the tests.
// Usage: wavepath-bench-coherence SCENE [WIDTH HEIGHT [RUNS]]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "bvh/device_buffers.h"
#include "bvh/gpu_scene.h"
#include "render/camera_lens.h"
#include "scene/gltf_loader.h"
#include "shaders/common/sampling.h"
#include "shaders/common/traverse.h"

namespace {

struct Ray {
  glm::vec3 origin;
  glm::vec3 direction;
};

// Spreads the low 10 bits of v to every third bit.
uint32_t spreadBits(uint32_t v) {
  v &= 0x3ffu;
  v = (v | (v << 16)) & 0x030000ffu;
  v = (v | (v << 8)) & 0x0300f00fu;
  v = (v | (v << 4)) & 0x030c30c3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

// Direction octant in the top 3 bits, a 27-bit Morton code of the origin below them.
uint32_t coherenceKey(const Ray& r, glm::vec3 lo, glm::vec3 extent) {
  glm::vec3 cell = glm::clamp((r.origin - lo) / extent, 0.0f, 1.0f) * 511.0f;
  uint32_t morton = spreadBits(uint32_t(cell.x)) | (spreadBits(uint32_t(cell.y)) << 1) |
                    (spreadBits(uint32_t(cell.z)) << 2);
  uint32_t octant = (r.direction.x < 0.0f ? 1u : 0u) | (r.direction.y < 0.0f ? 2u : 0u) |
                    (r.direction.z < 0.0f ? 4u : 0u);
  return (octant << 27) | morton;
}

std::vector<wp::gpu::Hit> traceAll(const wp::gpu::DeviceBuffers& buffers, const wp::GpuScene& scene,
                                   const std::vector<Ray>& rays) {
  std::vector<wp::gpu::Hit> hits(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    hits[i] = wp::gpu::traceClosest(buffers, scene.topLevelEntry(), uint32_t(scene.planes.size()), rays[i].origin,
                                    rays[i].direction, WP_FLT_MAX, 0.0f);
  }
  return hits;
}

// Median seconds of `runs` traces of `rays`.
double medianSeconds(const wp::gpu::DeviceBuffers& buffers, const wp::GpuScene& scene, const std::vector<Ray>& rays,
                     int runs) {
  std::vector<double> seconds;
  for (int run = 0; run < runs; ++run) {
    auto start = std::chrono::steady_clock::now();
    traceAll(buffers, scene, rays);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

// The rays in the order of `order`.
std::vector<Ray> reordered(const std::vector<Ray>& rays, const std::vector<uint32_t>& order) {
  std::vector<Ray> out;
  out.reserve(order.size());
  for (uint32_t i : order) {
    out.push_back(rays[i]);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 4 && argc != 5) {
    std::fprintf(stderr, "usage: wavepath-bench-coherence SCENE [WIDTH HEIGHT [RUNS]]\n");
    return 2;
  }
  const uint32_t width = argc >= 4 ? uint32_t(std::atoi(argv[2])) : 480;
  const uint32_t height = argc >= 4 ? uint32_t(std::atoi(argv[3])) : 270;
  const int runs = argc == 5 ? std::atoi(argv[4]) : 3;
  try {
    const wp::Scene scene = wp::loadScene(argv[1]);
    const wp::GpuScene packed = wp::packScene(scene);
    const wp::gpu::DeviceBuffers buffers = wp::sceneBuffers(packed);
    const wp::gpu::ThinLens lens = wp::makeLens(scene.camera, width, height);

    std::vector<Ray> camera;
    for (uint32_t y = 0; y < height; ++y) {
      for (uint32_t x = 0; x < width; ++x) {
        wp::gpu::CameraRay c = wp::gpu::sampleThinLensRay(lens, glm::vec2(float(x) + 0.5f, float(y) + 0.5f), width,
                                                          height, glm::vec2(0.5f));
        camera.push_back({c.origin, c.direction});
      }
    }
    const std::vector<wp::gpu::Hit> cameraHits = traceAll(buffers, packed, camera);

    // One bounce ray per camera ray that hit a triangle, about its geometric normal.
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<Ray> bounce;
    glm::vec3 lo(WP_FLT_MAX), hi(-WP_FLT_MAX);
    for (size_t i = 0; i < camera.size(); ++i) {
      const wp::gpu::Hit& h = cameraHits[i];
      if (h.instance == WP_INVALID || h.primitive == WP_INVALID) {
        continue;
      }
      const wp::gpu::GpuTriangle tri = buffers.triangles[h.primitive];
      const wp::gpu::GpuInstance inst = wp::gpu::instanceAt(buffers, h.instance, 0.0f);
      glm::vec3 n = glm::normalize(wp::gpu::normalToWorld(
          inst, glm::cross(wp::gpu::triangleEdge1(tri), wp::gpu::triangleEdge2(tri))));
      if (glm::dot(n, camera[i].direction) > 0.0f) {
        n = -n;
      }
      const glm::vec2 u(uniform(rng), uniform(rng));
      const glm::vec3 d =
          glm::normalize(wp::gpu::frameToWorld(wp::gpu::makeFrame(n), wp::gpu::sampleCosineHemisphere(u)));
      const glm::vec3 p = camera[i].origin + camera[i].direction * h.t;
      bounce.push_back({wp::gpu::offsetRayOrigin(p, n, d), d});
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    const glm::vec3 extent = glm::max(hi - lo, glm::vec3(1e-6f));

    std::vector<uint32_t> byKey(bounce.size());
    for (uint32_t i = 0; i < byKey.size(); ++i) {
      byKey[i] = i;
    }
    std::vector<uint32_t> shuffled = byKey;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(2));
    std::vector<uint32_t> keys(bounce.size());
    for (size_t i = 0; i < bounce.size(); ++i) {
      keys[i] = coherenceKey(bounce[i], lo, extent);
    }
    std::stable_sort(byKey.begin(), byKey.end(), [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });

    const std::vector<Ray> sorted = reordered(bounce, byKey);
    const std::vector<Ray> mixed = reordered(bounce, shuffled);
    // Every order must find the same hits: compare the sorted one's with the queue order's.
    const std::vector<wp::gpu::Hit> queueHits = traceAll(buffers, packed, bounce);
    const std::vector<wp::gpu::Hit> sortedHits = traceAll(buffers, packed, sorted);
    for (size_t i = 0; i < byKey.size(); ++i) {
      if (sortedHits[i].t != queueHits[byKey[i]].t) {
        std::fprintf(stderr, "bench-coherence: the sorted order found another hit for ray %u\n", byKey[i]);
        return 1;
      }
    }

    std::printf("%s, %ux%u: %zu camera rays, %zu bounce rays; one thread, medians of %d runs\n", argv[1], width,
                height, camera.size(), bounce.size(), runs);
    const double cameraSeconds = medianSeconds(buffers, packed, camera, runs);
    std::printf("  camera rays, pixel order      %7.2f Mrays/s\n", double(camera.size()) / cameraSeconds * 1e-6);
    const struct {
      const char* name;
      const std::vector<Ray>& rays;
    } orders[] = {{"bounce rays, queue order ", bounce}, {"bounce rays, sorted by key", sorted},
                  {"bounce rays, shuffled    ", mixed}};
    const double queueSeconds = medianSeconds(buffers, packed, bounce, runs);
    for (const auto& order : orders) {
      const double seconds = &order.rays == &bounce ? queueSeconds : medianSeconds(buffers, packed, order.rays, runs);
      std::printf("  %s     %7.2f Mrays/s  (%.2fx the queue order's time)\n", order.name,
                  double(order.rays.size()) / seconds * 1e-6, seconds / queueSeconds);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench-coherence: %s\n", e.what());
    return 1;
  }
  return 0;
}
