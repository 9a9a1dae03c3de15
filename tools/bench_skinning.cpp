// Host skinning benchmark: median time to pose a large skinned and morphed mesh (deformMesh),
// beside the time to pack the posed scene for the GPU (BVH build), which every pose needs too.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "bvh/gpu_scene.h"
#include "scene/mesh_deformation.h"

namespace {

double medianMs(std::vector<double> samples) {
  std::sort(samples.begin(), samples.end());
  return samples[samples.size() / 2];
}

template <typename F>
double timeMs(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  // A grid of `side` x `side` vertices (default about 1M), each weighted to 4 of 64 joints
  // (as glTF allows), with two morph targets with normals: a worst case per vertex.
  const int side = argc > 1 ? std::atoi(argv[1]) : 1000;
  const size_t vertices = size_t(side) * size_t(side);
  const uint32_t joints = 64;
  wp::MeshDeformation d;
  wp::Mesh mesh;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      d.restPositions.emplace_back(float(x) / float(side), float(y) / float(side), 0.0f);
      d.restNormals.emplace_back(0.0f, 0.0f, 1.0f);
      const uint32_t j = uint32_t(y) * joints / uint32_t(side);
      d.joints.emplace_back(j, (j + 1) % joints, (j + 2) % joints, (j + 3) % joints);
      d.jointWeights.emplace_back(0.4f, 0.3f, 0.2f, 0.1f);
    }
  }
  for (int t = 0; t < 2; ++t) {
    d.targets.push_back({std::vector<glm::vec3>(vertices, glm::vec3(0.0f, 0.0f, 0.01f * float(t + 1))),
                         std::vector<glm::vec3>(vertices, glm::vec3(0.01f, 0.0f, 0.0f))});
  }
  for (int y = 0; y + 1 < side; ++y) {
    for (int x = 0; x + 1 < side; ++x) {
      const uint32_t a = uint32_t(y * side + x);
      const uint32_t b = a + uint32_t(side);  // the vertex above a
      mesh.indices.insert(mesh.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  }
  mesh.materials.assign(mesh.indices.size() / 3, 0);
  std::vector<glm::mat4> jointMatrices;
  for (uint32_t j = 0; j < joints; ++j) {
    jointMatrices.push_back(glm::rotate(glm::mat4(1.0f), 0.01f * float(j), glm::vec3(0, 0, 1)));
  }

  std::vector<double> deform, pack;
  for (int run = 0; run < 5; ++run) {
    deform.push_back(timeMs([&] { wp::deformMesh(d, {0.3f, 0.6f}, jointMatrices, mesh); }));
  }
  wp::Scene scene;
  scene.materials.emplace_back();
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, glm::mat4(1.0f), false});
  for (int run = 0; run < 3; ++run) {
    pack.push_back(timeMs([&] { wp::packScene(scene); }));
  }
  std::printf("%zu vertices, %zu triangles: skinning + 2 morph targets %.1f ms, packScene (BVH build) %.1f ms "
              "(medians, one thread)\n",
              vertices, mesh.indices.size() / 3, medianMs(deform), medianMs(pack));
  return 0;
}
