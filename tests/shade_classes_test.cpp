// Shade classes (shade.comp): which scenes Vulkan shades with two pipelines, and that the
// split changes no pixel: the diffuse class defers every hit that needs glTF's BRDF to the
// second pipeline, which shades it as the single pipeline would, into the same path slot.
#include <gtest/gtest.h>

#include <memory>

#include "app/backend_factory.h"
#include "backend/vulkan/vulkan_backend.h"
#include "bvh/gpu_scene.h"
#include "render/wavefront.h"
#include "scene/gltf_loader.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

GpuScene packedAsset(const char* name) { return packScene(loadScene(sourceDirectory() / "assets" / name)); }

TEST(ShadeClasses, AreThoseOfTheMaterialsTheSurfacesUse) {
  // A Lambertian floor under glTF metals and glass: both classes.
  EXPECT_TRUE(packedAsset("materials.gltf").features().hasBothShadeClasses());
  // Every surface of the project's box is ideal diffuse, its lamp too: one class.
  GpuScene box = packedAsset("cornell-box.gltf");
  ASSERT_FALSE(box.features().hasBothShadeClasses());
  // A glTF material no surface uses costs no pipeline...
  gpu::GpuMaterial gltf = box.materials[0];
  gltf.info.x = WP_MATERIAL_GLTF;
  box.materials.push_back(gltf);
  EXPECT_FALSE(box.features().hasBothShadeClasses());
  // ...until a triangle has it.
  box.triangles[0].info.x = uint32_t(box.materials.size() - 1);
  EXPECT_TRUE(box.features().hasBothShadeClasses());
  // Unlit materials need none of the BRDF either.
  box.materials.back().info.x = WP_MATERIAL_UNLIT;
  EXPECT_FALSE(box.features().hasBothShadeClasses());
  // Every material glTF's: one class again.
  for (gpu::GpuMaterial& m : box.materials) m.info.x = WP_MATERIAL_GLTF;
  EXPECT_FALSE(box.features().hasBothShadeClasses());
}

// The accumulation of `asset` (small, a few samples, every bounce) rendered on Vulkan under
// the validation layer, with shade split by class or not.
Accumulation renderVulkan(const char* asset, bool split) {
  const BackendChoice choice{"vulkan", -1, true, "readback"};
  std::unique_ptr<Backend> backend = createBackend(choice);
  dynamic_cast<VulkanBackend&>(*backend).splitShadeByMaterial(split);
  const Scene scene = loadScene(sourceDirectory() / "assets" / asset);
  const GpuScene gpuScene = packScene(scene);
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.samplesPerPixel = 4;
  settings.maxBounces = 8;
  settings.maxPaths = 64 * 48 * 2;  // two passes
  WavefrontRenderer renderer(*backend, scene, gpuScene, settings);
  renderer.render(nullptr);
  checkValidation(choice);
  return backend->readAccumulation();
}

TEST(ShadeClasses, SplitShadeMakesTheSameImageBitForBit) {
  // Bit for bit, not within a tolerance: both runs trace the same paths from the same random
  // numbers and each vertex is shaded by the same code for its material, only in another
  // dispatch; a hit deferred and never shaded, or shaded by the diffuse pipeline as if
  // Lambertian, changes the radiance sums.
  for (const char* asset : {"materials.gltf", "animated.gltf"}) {
    SCOPED_TRACE(asset);
    const Accumulation split = renderVulkan(asset, true);
    const Accumulation single = renderVulkan(asset, false);
    double total = 0.0;
    for (const glm::vec4& s : split.sum) total += s.x + s.y + s.z;
    EXPECT_GT(total, 0.0) << "the split render is black";
    for (uint32_t layer = 0; layer < WP_ACCUMULATION_LAYERS; ++layer) {
      EXPECT_TRUE(*split.layers()[layer] == *single.layers()[layer]) << "layer " << layer << " differs";
    }
  }
}

}  // namespace
}  // namespace wp::test
