// How many paths a pass traces where the settings leave it to the device
// (defaultPathsInFlight, wavefront.h): 2^20 on a CPU implementation, such as the lavapipe and
// PoCL that CI has; a GPU's four times as many are measured on the GPU machines
// (docs/performance.md, "On a GPU"), which CI does not have.
#include <gtest/gtest.h>

#include <memory>

#include "app/backend_factory.h"
#include "bvh/gpu_scene.h"
#include "render/wavefront.h"
#include "support/asset_scene.h"

namespace wp::test {
namespace {

TEST(PathsInFlight, ACpuTraces2To20PathsAPassUnlessTheSettingsSayOtherwise) {
  const Scene scene = assetScene("cornell-box.gltf");
  const GpuScene gpuScene = packScene(scene);
  RenderSettings settings;
  settings.width = 2;
  settings.height = 1;
  settings.samplesPerPixel = (1u << 19) + 1;  // 2^20 + 2 paths: two passes of 2^20, one of the GPU's
  settings.maxBounces = 0;                    // camera rays and their light samples: quick
  for (const char* name : {"vulkan", "opencl"}) {
    SCOPED_TRACE(name);
    std::unique_ptr<Backend> backend = createBackend({name, -1, false, "readback"});
    ASSERT_TRUE(backend->onCpu()) << backend->deviceName() << ": CI's devices are CPU implementations";
    settings.maxPaths = 0;
    EXPECT_EQ(WavefrontRenderer(*backend, scene, gpuScene, settings).render(nullptr).passes, 2u);
    settings.maxPaths = 1u << 19;  // the user's choice stands
    EXPECT_EQ(WavefrontRenderer(*backend, scene, gpuScene, settings).render(nullptr).passes, 3u);
  }
}

}  // namespace
}  // namespace wp::test
