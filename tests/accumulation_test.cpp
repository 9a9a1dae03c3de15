// The per-pixel sums passes accumulate: what one path may add to them (finite, bounded), and
// that thousands of passes do not grow the process (the soak benchmark, tools/bench_soak.cpp,
// measures it over 10,000 samples per pixel).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "app/backend_factory.h"
#include "bvh/gpu_scene.h"
#include "render/wavefront.h"
#include "scene/gltf_loader.h"
#include "shaders/common/accumulation.h"
#include "support/asset_scene.h"

namespace wp::test {
namespace {

// Mappings of executable code in this process: each shader lavapipe compiles adds one.
size_t executableMappings() {
  std::ifstream maps("/proc/self/maps");
  size_t count = 0;
  for (std::string line; std::getline(maps, line);) {
    std::string range, permissions;
    std::istringstream(line) >> range >> permissions;
    count += permissions.find('x') != std::string::npos ? 1 : 0;
  }
  return count;
}

TEST(Accumulation, APathAddsAFiniteBoundedRadiance) {
  // 2^20 samples (--spp's limit) of the largest radiance, squared and summed, stay finite.
  const float largest = WP_MAX_SAMPLE_RADIANCE;
  EXPECT_TRUE(std::isfinite(largest * largest * float(1u << 20)));
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(gpu::accumulableRadiance(glm::vec3(0.5f, 2.0f, 1e15f)), glm::vec3(0.5f, 2.0f, 1e15f));  // untouched
  EXPECT_EQ(gpu::accumulableRadiance(glm::vec3(inf, 1e30f, -inf)), glm::vec3(largest, largest, -largest));
  EXPECT_EQ(gpu::accumulableRadiance(glm::vec3(nan, 3.0f, nan)), glm::vec3(0.0f, 3.0f, 0.0f));
}

TEST(LongRender, PassesCompileNoShaders) {
  // lavapipe (Mesa 22.3) compiled a new copy of every stage whose loops a uniform-buffer value
  // bounds at each bind, and kept them all: 150 KB a pass, 100 MB over a 10,000-spp render.
  // RenderParams is read at an entry given by a push constant since, not at a constant offset
  // (bindings.glsl); 60 passes here compiled about 60 shaders before, and do again with the
  // entry a constant.
  const Scene scene = assetScene("cornell-box.gltf");
  const GpuScene gpuScene = packScene(scene);
  std::unique_ptr<Backend> backend = createBackend({"vulkan", -1, false, "readback"});
  RenderSettings settings;
  settings.width = 16;
  settings.height = 16;
  settings.maxPaths = 256;  // one sample of every pixel a pass
  settings.samplesPerPixel = 10;
  WavefrontRenderer warmUp(*backend, scene, gpuScene, settings);
  warmUp.render(nullptr);  // the first binds compile what they compile
  const size_t before = executableMappings();
  settings.samplesPerPixel = 60;
  WavefrontRenderer renderer(*backend, scene, gpuScene, settings);
  const RenderStats stats = renderer.render(nullptr);
  ASSERT_EQ(stats.passes, 60u);
  EXPECT_LE(executableMappings(), before + 2) << "shaders compiled during " << stats.passes << " passes";
}

}  // namespace
}  // namespace wp::test
