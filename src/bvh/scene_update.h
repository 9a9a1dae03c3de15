// Per-frame update of a packed scene to a new pose of the same scene: refits the bottom
// levels of deforming meshes and rebuilds the top level and the light table.
#pragma once

#include <cstdint>
#include <vector>

#include "bvh/gpu_scene.h"
#include "bvh/gpu_scene_parts.h"

namespace wp {

// A refitted bottom level is rebuilt once its SAH cost exceeds the cost at its last build by
// this factor. Read off the 100-frame curve in docs/animation.md: at 1.2 a deforming mesh
// is rebuilt 4 times in 100 frames and its trees cost 6% more than fresh builds on average
// (1.3: 2 rebuilds, 9%; 1.1: 7, 3%). A rebuild costs about 6 refits with their triangle
// records and traversal is most of a frame's render time, so tighter thresholds pay while a
// frame takes longer than a rebuild (a path-traced frame of such a mesh does), looser ones
// in a viewer drawing cheap frames, which can pass its own.
inline constexpr float kRebuildSahRatio = 1.2f;

// Wall time of the parts of one update, in milliseconds.
struct SceneUpdateTimes {
  double refitMs = 0.0;      // deforming meshes: triangle bounds, refits, GPU nodes
  double rebuildMs = 0.0;    // bottom-level rebuilds that the SAH threshold triggered
  double trianglesMs = 0.0;  // deforming meshes: triangle and shading records
  double tlasMs = 0.0;       // instance bounds, top-level build, its GPU nodes
  double lightsMs = 0.0;     // instance records, world-space light table, sky choice
  uint32_t refits = 0;       // bottom levels refitted (rebuilt ones included)
  uint32_t rebuilds = 0;     // bottom levels rebuilt
  double totalMs() const { return refitMs + rebuildMs + trianglesMs + tlasMs + lightsMs; }
};

// Keeps a packed scene up to date with the poses of an animation. Static meshes are packed
// once; per pose, meshes marked Mesh::deforming get their bottom level refitted (the tree
// keeps its topology; rebuilt past rebuildSahRatio), every instance and sphere gets its new
// transform under a rebuilt top level, and the light table is recomputed. The result holds
// what packScene(posed) holds, except that refitted trees group triangles as they were
// grouped when last built (same hits, other node and triangle order).
class SceneUpdater {
public:
  // Packs the first pose. Requires what packScene requires; rebuildSahRatio >= 1.
  explicit SceneUpdater(const Scene& first, float rebuildSahRatio = kRebuildSahRatio);

  // Updates to `posed`. Requires the meshes, instances and spheres of the first pose in the
  // same order, meshes with the same indices and materials (only positions and normals of
  // deforming meshes and the transforms change); throws wp::Error on a different count.
  const GpuScene& update(const Scene& posed);

  const GpuScene& scene() const { return gpu_; }
  const SceneUpdateTimes& times() const { return times_; }
  // SAH cost of a mesh's bottom level now, over its cost when last built (1 for meshes
  // that never deform).
  float sahGrowth(uint32_t mesh) const;

private:
  void checkPose(const Scene& posed) const;
  // Writes every bottom level again from mesh 0 on, after a rebuild changed a node count.
  void relayoutNodes();
  // Where mesh m's block of nodes ends: bottom levels lie in mesh order, the top level after
  // them, so at the next mesh's root or the top level's.
  uint32_t nodeBlockEnd(size_t m) const;

  GpuScene gpu_;
  std::vector<pack_detail::PackedMesh> meshes_;
  std::vector<float> builtSah_;  // per mesh: sahCost at its last build
  std::vector<bool> deforming_;  // per mesh, as in the first pose
  std::vector<uint32_t> instanceMeshes_;  // per instance of the first pose: its mesh
  size_t sphereCount_ = 0;
  float rebuildSahRatio_;
  SceneUpdateTimes times_;
};

}  // namespace wp
