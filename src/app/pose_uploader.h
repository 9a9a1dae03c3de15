// The GPU form of each pose of an animated scene, shared by image sequences and the viewer.
#pragma once

#include <optional>

#include "bvh/gpu_scene.h"
#include "bvh/scene_update.h"
#include "scene/scene.h"

namespace wp {

// The first pose is packed whole; later ones reuse its bottom-level BVHs (refitted where
// meshes deform) under a rebuilt top level, as SceneUpdater does.
class PoseUploader {
public:
  // The packed form of `posed`. Requires every call to pass a pose of the same scene (see
  // SceneUpdater::update); the result stays valid, and is updated in place, until the next call.
  const GpuScene& gpuSceneOf(const Scene& posed);
  // The packed form of the last pose. Requires gpuSceneOf to have been called.
  const GpuScene& gpuScene() const { return updater_->scene(); }
  // The parts of the last update; null while only the first pose was packed.
  const SceneUpdateTimes* lastUpdate() const { return updated_ ? &updater_->times() : nullptr; }

private:
  std::optional<SceneUpdater> updater_;
  bool updated_ = false;
};

}  // namespace wp
