// Packs the first pose of a scene and updates the packed scene to later ones.
#include "app/pose_uploader.h"

#include "bvh/instance_baking.h"

namespace wp {

const GpuScene& PoseUploader::gpuSceneOf(const Scene& posed) {
  Scene baked = bakeSingleUseMeshes(posed);
  if (!updater_) {
    updater_.emplace(baked);
    return updater_->scene();
  }
  updated_ = true;
  return updater_->update(baked);
}

}  // namespace wp
