// A packed scene as the DeviceBuffers bundle that the portable headers take, for host code
// that runs them (autofocus, tests): the scene arrays set, the path state left null.
#pragma once

#include "bvh/gpu_scene.h"
#include "shaders/common/binding_table.h"

namespace wp {

// Points into `scene`, which must outlive the result and stay unchanged.
gpu::DeviceBuffers sceneBuffers(const GpuScene& scene);

}  // namespace wp
