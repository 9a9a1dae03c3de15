// What Vulkan builds for a scene: the stages specialized to the scene's features
// (prelude_glsl.h) and shade split by class (shade.comp). Which scenes get which, and that
// neither changes a pixel: the diffuse class defers every hit that needs glTF's BRDF to the
// second pipeline, which shades it as the single pipeline would, into the same path slot, and
// the code a feature's constant compiles away is code the scene never runs.
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

// Every material of `scene` without metalness (GpuMaterial.surface.x 0).
void removeMetalness(GpuScene& scene) {
  for (gpu::GpuMaterial& m : scene.materials) m.surface.x = 0.0f;
}

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

TEST(SceneFeatures, MetallicOnlyWhereAUsedMaterialHasMetalness) {
  // glTF's default metalness is 1: materials.gltf's metals and its lamp's default both count.
  EXPECT_TRUE(packedAsset("materials.gltf").features().metallic);
  GpuScene box = packedAsset("cornell-box.gltf");
  for (gpu::GpuMaterial& m : box.materials) m.info.x = WP_MATERIAL_GLTF;
  removeMetalness(box);
  SceneFeatures f = box.features();
  EXPECT_TRUE(f.microfacet);
  EXPECT_FALSE(f.metallic) << "no material has metalness";
  // A metal no surface has adds no code...
  gpu::GpuMaterial metal = box.materials[0];
  metal.surface.x = 0.5f;
  box.materials.push_back(metal);
  EXPECT_FALSE(box.features().metallic);
  // ...until a triangle has it.
  box.triangles[0].info.x = uint32_t(box.materials.size() - 1);
  EXPECT_TRUE(box.features().metallic);
  // Ideal diffuse materials have no metal lobe, whatever their factor.
  box.materials.back().info.x = WP_MATERIAL_LAMBERT;
  EXPECT_FALSE(box.features().metallic);
}

TEST(SceneFeatures, EmissiveWhereAUsedMaterialEmits) {
  GpuScene box = packedAsset("cornell-box.gltf");
  EXPECT_TRUE(box.features().emissive) << "the box's lamp";
  for (gpu::GpuMaterial& m : box.materials) m.emission = glm::vec4(0.0f, 0.0f, 0.0f, m.emission.w);
  EXPECT_FALSE(box.features().emissive) << "no emission left";
  // An unlit material glows with its colour (integrator.h).
  for (gpu::GpuMaterial& m : box.materials) m.info.x = WP_MATERIAL_UNLIT;
  EXPECT_TRUE(box.features().emissive);
}

TEST(SceneFeatures, SkySampledWhereNextEventEstimationSamplesTheSky) {
  GpuScene spheres = packedAsset("sky-spheres.gltf");
  ASSERT_GT(spheres.sky.selectionProbability, 0.0f) << "sky-spheres.gltf is lit by its sky";
  EXPECT_TRUE(spheres.features().skySampled);
  spheres.sky.selectionProbability = 0.0f;
  EXPECT_FALSE(spheres.features().skySampled);
}

// How renderVulkan builds the stages and the scene.
struct VulkanBuild {
  bool split = true;            // shade split by class where the scene has both
  bool specialize = true;       // the stages specialized to the scene's features
  bool withoutMetal = false;    // every material's metalness 0 (removeMetalness)
  bool solidAngle = false;      // lights selected by solid angle, not by power
};

// The accumulation of `asset` (small, a few samples, every bounce) rendered on Vulkan under
// the validation layer, built as `build` says.
Accumulation renderVulkan(const char* asset, VulkanBuild build) {
  const BackendChoice choice{"vulkan", -1, true, "readback"};
  std::unique_ptr<Backend> backend = createBackend(choice);
  dynamic_cast<VulkanBackend&>(*backend).splitShadeByMaterial(build.split);
  dynamic_cast<VulkanBackend&>(*backend).specializeToScene(build.specialize);
  const Scene scene = loadScene(sourceDirectory() / "assets" / asset);
  GpuScene gpuScene = packScene(scene);
  if (build.withoutMetal) removeMetalness(gpuScene);
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.samplesPerPixel = 4;
  settings.maxBounces = 8;
  settings.maxPaths = 64 * 48 * 2;  // two passes
  settings.lightSelection = build.solidAngle ? LightSelection::SolidAngle : LightSelection::Power;
  WavefrontRenderer renderer(*backend, scene, gpuScene, settings);
  renderer.render(nullptr);
  checkValidation(choice);
  return backend->readAccumulation();
}

// Every layer of `a` and `b` the same, bit for bit, and `a` not black.
void expectSameBitForBit(const Accumulation& a, const Accumulation& b) {
  double total = 0.0;
  for (const glm::vec4& s : a.sum) total += s.x + s.y + s.z;
  EXPECT_GT(total, 0.0) << "the render is black";
  for (uint32_t layer = 0; layer < WP_ACCUMULATION_LAYERS; ++layer) {
    EXPECT_TRUE(*a.layers()[layer] == *b.layers()[layer]) << "layer " << layer << " differs";
  }
}

TEST(ShadeClasses, SplitShadeMakesTheSameImageBitForBit) {
  // Bit for bit, not within a tolerance: both runs trace the same paths from the same random
  // numbers and each vertex is shaded by the same code for its material, only in another
  // dispatch; a hit deferred and never shaded, or shaded by the diffuse pipeline as if
  // Lambertian, changes the radiance sums.
  for (const char* asset : {"materials.gltf", "animated.gltf"}) {
    SCOPED_TRACE(asset);
    expectSameBitForBit(renderVulkan(asset, {.split = true}), renderVulkan(asset, {.split = false}));
  }
}

TEST(SceneFeatures, StagesSpecializedToTheSceneMakeTheSameImageBitForBit) {
  // Bit for bit too: a feature's constant may only remove code that the scene never runs (a
  // metal lobe of weight 0, glass of transmission 0, the sky's sampling at probability 0,
  // emission nothing has). The project's box turns the material features off (its materials
  // are ideal diffuse), materials.gltf keeps most, sky-spheres.gltf samples its sky, and
  // lamps.gltf without metalness keeps glTF's BRDF without its metal lobe; between them each
  // of the constants below is on in one case and off in another. The light selection is the
  // render's: power everywhere but in the last case, which selects lamps.gltf's lights by
  // solid angle (its constant on).
  struct Case {
    const char* asset;
    bool withoutMetal;
    bool solidAngle = false;
  };
  std::vector<SceneFeatures> covered;
  for (const Case c : {Case{"cornell-box.gltf", false}, Case{"materials.gltf", false}, Case{"sky-spheres.gltf", false},
                       Case{"lamps.gltf", true}, Case{"lamps.gltf", false, true}}) {
    SCOPED_TRACE(c.asset);
    GpuScene scene = packedAsset(c.asset);
    if (c.withoutMetal) removeMetalness(scene);
    covered.push_back(scene.features());
    expectSameBitForBit(
        renderVulkan(c.asset, {.specialize = true, .withoutMetal = c.withoutMetal, .solidAngle = c.solidAngle}),
        renderVulkan(c.asset, {.specialize = false, .withoutMetal = c.withoutMetal, .solidAngle = c.solidAngle}));
  }
  auto both = [&](bool SceneFeatures::*feature) {
    bool on = false;
    bool off = false;
    for (const SceneFeatures& f : covered) (f.*feature ? on : off) = true;
    return on && off;
  };
  EXPECT_TRUE(both(&SceneFeatures::microfacet));
  EXPECT_TRUE(both(&SceneFeatures::metallic));
  EXPECT_TRUE(both(&SceneFeatures::emissive));
  EXPECT_TRUE(both(&SceneFeatures::skySampled));
}

}  // namespace
}  // namespace wp::test
