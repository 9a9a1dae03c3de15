// A packed scene as the DeviceBuffers bundle of the portable headers.
#include "bvh/device_buffers.h"

namespace wp {

gpu::DeviceBuffers sceneBuffers(const GpuScene& scene) {
  gpu::DeviceBuffers buffers{};
  // Each scene array of the binding table is the GpuScene member of the same name.
#define WP_SCENE_ARRAY(name) buffers.name = scene.name.data();
  WP_FOR_EACH_SCENE_ARRAY
#undef WP_SCENE_ARRAY
  return buffers;
}

}  // namespace wp
