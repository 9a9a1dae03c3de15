// Per-frame update of a packed scene: bottom-level refits with an SAH-triggered rebuild, a
// fresh top level and light table.
#include "bvh/scene_update.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>

#include "bvh/bvh_refit.h"
#include "core/error.h"

namespace wp {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

SceneUpdater::SceneUpdater(const Scene& first, float rebuildSahRatio) : rebuildSahRatio_(rebuildSahRatio) {
  if (!(rebuildSahRatio >= 1.0f)) {
    throw Error("scene update: rebuild SAH ratio " + std::to_string(rebuildSahRatio) +
                " is below 1; pass a ratio >= 1 (infinity never rebuilds)");
  }
  gpu_ = pack_detail::packSceneParts(first, meshes_);
  for (const pack_detail::PackedMesh& mesh : meshes_) {
    builtSah_.push_back(mesh.sah);
  }
  deforming_.resize(first.meshes.size());
  for (size_t m = 0; m < first.meshes.size(); ++m) {
    deforming_[m] = first.meshes[m].deforming;
  }
  instanceMeshes_.reserve(first.instances.size());
  for (const MeshInstance& inst : first.instances) {
    instanceMeshes_.push_back(inst.mesh);
  }
  sphereCount_ = first.spheres.size();
}

float SceneUpdater::sahGrowth(uint32_t mesh) const {
  return builtSah_[mesh] > 0.0f ? meshes_[mesh].sah / builtSah_[mesh] : 1.0f;
}

void SceneUpdater::checkPose(const Scene& posed) const {
  auto fail = [](const std::string& what) {
    throw Error("scene update: " + what + "; pose the scene the updater was made from");
  };
  if (posed.meshes.size() != gpu_.meshes.size()) {
    fail(std::to_string(posed.meshes.size()) + " meshes, the first pose had " + std::to_string(gpu_.meshes.size()));
  }
  for (size_t m = 0; m < posed.meshes.size(); ++m) {
    const Mesh& mesh = posed.meshes[m];
    if (mesh.triangleCount() != gpu_.meshes[m].triangleCount || mesh.deforming != deforming_[m]) {
      fail("mesh " + std::to_string(m) + " ('" + mesh.name + "') changed its triangle count or deforming flag");
    }
  }
  if (posed.instances.size() != instanceMeshes_.size() || posed.spheres.size() != sphereCount_) {
    fail("the number of instances or spheres changed");
  }
  for (size_t i = 0; i < posed.instances.size(); ++i) {
    if (posed.instances[i].mesh != instanceMeshes_[i]) {
      fail("instance " + std::to_string(i) + " places another mesh");
    }
  }
}

const GpuScene& SceneUpdater::update(const Scene& posed) {
  checkPose(posed);
  times_ = {};
  // The top level always follows the bottom levels; it is rebuilt below.
  gpu_.nodes.resize(gpu_.tlasRoot);
  bool relayout = false;
  for (uint32_t m = 0; m < posed.meshes.size(); ++m) {
    const Mesh& mesh = posed.meshes[m];
    if (!mesh.deforming || mesh.triangleCount() == 0) {
      continue;
    }
    pack_detail::PackedMesh& packed = meshes_[m];
    const GpuMeshRange& range = gpu_.meshes[m];
    auto start = Clock::now();
    pack_detail::MeshPrimitives prims = pack_detail::meshPrimitives(posed, mesh);
    const uint32_t blockEnd = nodeBlockEnd(m);
    refitBvh(packed.bvh, prims.bounds);
    packed.sah = sahCost(packed.bvh);
    ++times_.refits;
    times_.refitMs += millisecondsSince(start);
    if (packed.sah > builtSah_[m] * rebuildSahRatio_) {
      start = Clock::now();
      packed.bvh = pack_detail::buildMeshBvh(prims);
      packed.sah = builtSah_[m] = sahCost(packed.bvh);
      packed.wide = collapseToWide(packed.bvh);
      ++times_.rebuilds;
      times_.rebuildMs += millisecondsSince(start);
    }
    packed.bounds = packed.bvh.nodes[0].bounds;

    start = Clock::now();
    std::vector<gpu::BvhNode> nodes = wideNodes(packed.bvh, packed.wide, range.firstTriangle, range.rootNode);
    if (nodes.size() == blockEnd - range.rootNode) {
      std::copy(nodes.begin(), nodes.end(), gpu_.nodes.begin() + range.rootNode);
    } else {
      relayout = true;
    }
    times_.refitMs += millisecondsSince(start);
    start = Clock::now();
    pack_detail::writeTriangles(posed, mesh, packed.bvh, prims, range.firstTriangle, gpu_);
    packed.emitters = std::move(prims.emitters);
    times_.trianglesMs += millisecondsSince(start);
  }
  if (relayout) {
    auto start = Clock::now();
    relayoutNodes();
    times_.rebuildMs += millisecondsSince(start);
  }

  double weightedSah = 0.0;
  for (size_t m = 0; m < meshes_.size(); ++m) {
    weightedSah += static_cast<double>(meshes_[m].sah) * static_cast<double>(gpu_.meshes[m].triangleCount);
  }
  gpu_.sahCost = gpu_.triangleCount ? weightedSah / static_cast<double>(gpu_.triangleCount) : 0.0;

  pack_detail::InstanceLevelSeconds instanceLevel = pack_detail::packInstances(posed, meshes_, gpu_);
  times_.tlasMs = 1e3 * instanceLevel.tlas;
  times_.lightsMs = 1e3 * instanceLevel.lights;
  gpu_.bvhBuildSeconds = 1e-3 * (times_.refitMs + times_.rebuildMs + times_.tlasMs);
  return gpu_;
}

uint32_t SceneUpdater::nodeBlockEnd(size_t m) const {
  return m + 1 < gpu_.meshes.size() ? gpu_.meshes[m + 1].rootNode : gpu_.tlasRoot;
}

void SceneUpdater::relayoutNodes() {
  // Each mesh's old block is read before its root moves, and the blocks after it (and the
  // top level's start, already cut off) move only later.
  std::vector<gpu::BvhNode> nodes;
  for (size_t m = 0; m < gpu_.meshes.size(); ++m) {
    GpuMeshRange& range = gpu_.meshes[m];
    if (deforming_[m] && range.triangleCount > 0) {
      range.rootNode = appendWideNodes(meshes_[m].bvh, meshes_[m].wide, range.firstTriangle, nodes);
      continue;
    }
    const uint32_t oldStart = range.rootNode;
    const uint32_t oldEnd = nodeBlockEnd(m);
    range.rootNode = static_cast<uint32_t>(nodes.size());
    // Interior child indices are absolute, so they move with the block.
    uint32_t shift = range.rootNode - oldStart;
    for (uint32_t i = oldStart; i < oldEnd; ++i) {
      gpu::BvhNode node = gpu_.nodes[i];
      for (uint32_t slot = 0; slot < WP_BVH_WIDTH; ++slot) {
        if (node.childCount[slot] == 0 && node.childIndex[slot] != WP_INVALID) {
          node.childIndex[slot] += shift;
        }
      }
      nodes.push_back(node);
    }
  }
  gpu_.nodes = std::move(nodes);
  gpu_.tlasRoot = static_cast<uint32_t>(gpu_.nodes.size());
}

}  // namespace wp
