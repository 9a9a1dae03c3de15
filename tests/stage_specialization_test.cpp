// What Vulkan builds for a scene: the stages specialized to the scene's features
// (prelude_glsl.h) and shade split by class (shade.comp). Which scenes get which, and that
// neither changes a pixel: the diffuse class defers every hit that needs glTF's BRDF to the
// second pipeline, which shades it as the single pipeline would, into the same path slot, and
// the code a feature's constant compiles away is code the scene never runs.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <random>

#include "app/backend_factory.h"
#include "backend/opencl/opencl_backend.h"
#include "backend/vulkan/vulkan_backend.h"
#include "bvh/gpu_scene.h"
#include "bvh/instance_baking.h"
#include "image/feature_passes.h"
#include "render/wavefront.h"
#include "scene/environment_map.h"
#include "scene/gltf_loader.h"
#include "support/asset_scene.h"
#include "support/run_wavepath.h"
#include "support/same_accumulation.h"

namespace wp::test {
namespace {

GpuScene packedAsset(const char* name) { return packScene(assetScene(name)); }

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

TEST(SceneFeatures, PlanesWhereTheSceneHasPlanes) {
  EXPECT_TRUE(packedAsset("sky-spheres.gltf").features().planes);
  GpuScene box = packedAsset("cornell-box.gltf");
  EXPECT_FALSE(box.features().planes);
  box.planes.push_back(gpu::GpuPlane{});
  EXPECT_TRUE(box.features().planes);
}

TEST(SceneFeatures, SpheresWhereTheSceneHasSpheres) {
  EXPECT_TRUE(packedAsset("sky-spheres.gltf").features().spheres);
  GpuScene box = packedAsset("cornell-box.gltf");
  EXPECT_FALSE(box.features().spheres) << "glTF meshes alone";
  // A sphere placed among the box's instances...
  gpu::GpuInstance sphere = box.instances[0];
  sphere.info.x = WP_INSTANCE_SPHERE;
  box.instances.insert(box.instances.begin() + box.placedInstances, sphere);
  ++box.placedInstances;
  EXPECT_TRUE(box.features().spheres);
  // ...and only there: the motion keys after the placed instances are not instances.
  --box.placedInstances;
  EXPECT_FALSE(box.features().spheres);
}

// The assets' sky map (assets/sky.hdr), which tests give a scene as --sky does.
EnvironmentMap assetSkyMap() { return loadEnvironmentMap(sourceDirectory() / "assets" / "sky.hdr"); }

TEST(SceneFeatures, SkyMapWhereTheSkyHasMoreThanOneTexel) {
  Scene scene = assetScene("sky-spheres.gltf");
  EXPECT_FALSE(packScene(scene).features().skyMap) << "the default white sky, one texel";
  scene.sky = assetSkyMap();
  ASSERT_GT(scene.sky.width * scene.sky.height, 1u);
  EXPECT_TRUE(packScene(scene).features().skyMap);
  scene.sky = makeEnvironmentMap(1, 1, {glm::vec3(0.2f, 0.3f, 0.4f)});
  EXPECT_FALSE(packScene(scene).features().skyMap) << "--sky-color: one texel";
}

// A spot lamp in the project's box, under its ceiling light, aimed at the floor: the box then
// has lights of both kinds, emissive triangles and a punctual one.
Scene boxWithSpotLamp() {
  Scene scene = assetScene("cornell-box.gltf");
  PunctualLight lamp;
  lamp.kind = PunctualLight::Kind::Spot;
  lamp.intensity = glm::vec3(0.3f);
  lamp.outerConeAngle = 0.6f;
  lamp.innerConeAngle = 0.3f;
  // Its -Z turned down (-y), from above the middle of the floor (the box spans 0.55 on each axis).
  lamp.lightToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0.28f, 0.45f, 0.28f)) *
                      glm::rotate(glm::mat4(1.0f), glm::radians(-90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  scene.lights.push_back(lamp);
  return scene;
}

TEST(SceneFeatures, PunctualWhereTheSceneHasPunctualLights) {
  EXPECT_TRUE(packedAsset("lamps.gltf").features().punctual);
  EXPECT_FALSE(packedAsset("cornell-box.gltf").features().punctual) << "an emissive quad alone";
  const SceneFeatures both = packScene(boxWithSpotLamp()).features();
  EXPECT_TRUE(both.punctual);
  EXPECT_TRUE(both.emissive);
}

TEST(SceneFeatures, InstancedWhereTheTopLevelsRootIsANode) {
  // The project's box as the renderer packs it: every mesh placed once, baked into one
  // instance, whose leaf the traversal starts from.
  GpuScene box = packScene(bakeSingleUseMeshes(assetScene("cornell-box.gltf")));
  ASSERT_EQ(box.placedInstances, 1u);
  EXPECT_EQ(box.topLevelEntry(), gpu::packEntry(0u, 1u));
  EXPECT_FALSE(box.features().instanced);
  // Unbaked, its eight meshes are eight instances under a root node.
  EXPECT_TRUE(packedAsset("cornell-box.gltf").features().instanced);
  // Spheres are instances of their own: several, under a root node.
  GpuScene spheres = packedAsset("sky-spheres.gltf");
  ASSERT_GT(spheres.placedInstances, 1u);
  EXPECT_EQ(spheres.topLevelEntry(), gpu::packEntry(spheres.tlasRoot, 0u));
  EXPECT_TRUE(spheres.features().instanced);
  // No instance at all: an empty root node.
  Scene nothing;
  nothing.materials.resize(1);
  GpuScene empty = packScene(nothing);
  EXPECT_EQ(empty.topLevelEntry(), gpu::packEntry(empty.tlasRoot, 0u));
  EXPECT_TRUE(empty.features().instanced);
}

// The project's box with texture coordinates on every wall, (x + z, y + z) times 3, which no
// face of the box sees as degenerate (a normal map's frame is their gradient), and two 4x4
// textures of random texels: texture 0 colour (sRGB), texture 1 data (linear). Its materials
// fill no slot yet.
Scene texturedBox() {
  Scene scene = assetScene("cornell-box.gltf");
  for (Mesh& mesh : scene.meshes) {
    mesh.uvs.clear();
    for (const glm::vec3& p : mesh.positions) mesh.uvs.push_back(3.0f * glm::vec2(p.x + p.z, p.y + p.z));
  }
  std::mt19937 random(7);
  for (bool srgb : {true, false}) {
    Texture texture;
    texture.width = texture.height = 4;
    for (int i = 0; i < 16; ++i) texture.rgba.push_back(uint32_t(random()) | 0xff000000u);
    texture.srgb = srgb;
    scene.textures.push_back(texture);
  }
  return scene;
}

// Each material texture slot, the scene feature that compiles its lookups in, and whether it
// holds colour (texture 0 of texturedBox) or data (texture 1).
struct TextureSlot {
  int Material::*slot;
  bool SceneFeatures::*feature;
  bool colour;
};
const TextureSlot kTextureSlots[] = {
    {&Material::baseColorTexture, &SceneFeatures::baseColorTexture, true},
    {&Material::metallicRoughnessTexture, &SceneFeatures::metallicRoughnessTexture, false},
    {&Material::normalTexture, &SceneFeatures::normalTexture, false},
    {&Material::emissiveTexture, &SceneFeatures::emissiveTexture, true},
    {&Material::specularTexture, &SceneFeatures::extensionTextures, false},
    {&Material::specularColorTexture, &SceneFeatures::extensionTextures, true},
    {&Material::sheenColorTexture, &SceneFeatures::extensionTextures, true},
    {&Material::sheenRoughnessTexture, &SceneFeatures::extensionTextures, false},
    {&Material::clearcoatTexture, &SceneFeatures::extensionTextures, false},
    {&Material::clearcoatRoughnessTexture, &SceneFeatures::extensionTextures, false},
    {&Material::clearcoatNormalTexture, &SceneFeatures::extensionTextures, false}};
const std::pair<const char*, bool SceneFeatures::*> kTextureFeatures[] = {
    {"base colour", &SceneFeatures::baseColorTexture},
    {"metallic-roughness", &SceneFeatures::metallicRoughnessTexture},
    {"normal", &SceneFeatures::normalTexture},
    {"emissive", &SceneFeatures::emissiveTexture},
    {"extensions'", &SceneFeatures::extensionTextures}};

TEST(SceneFeatures, TextureSlotsAreThoseTheUsedMaterialsFill) {
  for (const auto& [name, feature] : kTextureFeatures) {
    EXPECT_FALSE(packScene(texturedBox()).features().*feature) << name << ": no material has a texture";
  }
  for (const TextureSlot& slot : kTextureSlots) {
    Scene scene = texturedBox();
    // A material no surface has fills the slot: no code for it...
    Material unused = scene.materials[0];
    unused.*slot.slot = slot.colour ? 0 : 1;
    scene.materials.push_back(unused);
    for (const auto& [name, feature] : kTextureFeatures) {
      EXPECT_FALSE(packScene(scene).features().*feature) << name;
    }
    // ...until a triangle has it; the other slots' features stay off.
    scene.meshes[0].materials[0] = uint32_t(scene.materials.size() - 1);
    const SceneFeatures f = packScene(scene).features();
    for (const auto& [name, feature] : kTextureFeatures) {
      EXPECT_EQ(f.*feature, feature == slot.feature) << name;
    }
  }
}

// The textured box with the slots `filled` (members of kTextureSlots) filled on glTF materials
// with a sheen and a clear coat, so that each slot's texture changes the image.
Scene texturedBoxFilling(const std::vector<int Material::*>& filled) {
  Scene scene = texturedBox();
  for (Material& m : scene.materials) {
    m.bsdf = Material::Bsdf::Gltf;
    m.metallic = 0.3f;
    m.roughness = 0.5f;
    m.sheenColor = glm::vec3(0.5f);
    m.sheenRoughness = 0.5f;
    m.clearcoat = 0.5f;
    m.clearcoatRoughness = 0.2f;
    for (const TextureSlot& slot : kTextureSlots) {
      if (std::find(filled.begin(), filled.end(), slot.slot) != filled.end()) m.*slot.slot = slot.colour ? 0 : 1;
    }
  }
  return scene;
}

// How renderVulkan and renderOpenCl build the stages and the scene.
struct StageBuild {
  bool split = true;            // shade split by class where the scene has both (Vulkan)
  bool specialize = true;       // the stages specialized to the scene's features
  bool withoutMetal = false;    // every material's metalness 0 (removeMetalness)
  bool solidAngle = false;      // lights selected by solid angle, not by power
  bool featurePasses = true;    // the render records the feature passes
  SamplerKind sampler = SamplerKind::Sobol;
  uint32_t maxBounces = 8;
  StackPlacement* placedStacks = nullptr;  // where Vulkan's stages kept their stacks, if given
};

// Renders `scene` (small, a few samples, every bounce) on `backend` as `build` says and
// returns the accumulation.
Accumulation renderOn(Backend& backend, const Scene& scene, const StageBuild& build) {
  GpuScene gpuScene = packScene(scene);
  if (build.withoutMetal) removeMetalness(gpuScene);
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.samplesPerPixel = 4;
  settings.maxBounces = build.maxBounces;
  settings.maxPaths = 64 * 48 * 2;  // two passes
  settings.lightSelection = build.solidAngle ? LightSelection::SolidAngle : LightSelection::Power;
  settings.featurePasses = build.featurePasses;
  settings.sampler = build.sampler;
  WavefrontRenderer renderer(backend, scene, gpuScene, settings);
  renderer.render(nullptr);
  return backend.readAccumulation();
}

// The accumulation of `scene` rendered on Vulkan under the validation layer, built as `build`
// says.
Accumulation renderVulkan(const Scene& scene, StageBuild build) {
  const BackendChoice choice{"vulkan", -1, true, "readback"};
  std::unique_ptr<Backend> backend = createBackend(choice);
  auto& vulkan = dynamic_cast<VulkanBackend&>(*backend);
  vulkan.splitShadeByMaterial(build.split);
  vulkan.specializeToScene(build.specialize);
  Accumulation accumulation = renderOn(*backend, scene, build);
  checkValidation(choice);
  if (build.placedStacks) *build.placedStacks = vulkan.stackPlacement();
  return accumulation;
}

// The same on OpenCL (PoCL), its kernels built with warnings as errors and its queue counters
// checked.
Accumulation renderOpenCl(const Scene& scene, StageBuild build) {
  const BackendChoice choice{"opencl", -1, true, "readback"};
  std::unique_ptr<Backend> backend = createBackend(choice);
  dynamic_cast<OpenClBackend&>(*backend).specializeToScene(build.specialize);
  return renderOn(*backend, scene, build);
}

Accumulation renderVulkan(const char* asset, StageBuild build) {
  return renderVulkan(assetScene(asset), build);
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
  // emission nothing has, the walk of a top level that holds one instance, the planes' loop
  // of a scene without planes, the spheres' intersection and surface in a scene of meshes, the
  // sky map's coordinates under a uniform sky, the punctual lights' sampling in a scene lit by
  // emitters alone). The project's box turns the material features off (its materials are
  // ideal diffuse), its top level holds one instance and it has no planes and no punctual
  // lights, materials.gltf keeps most, sky-spheres.gltf samples its sky map among spheres and
  // planes, lamps.gltf without metalness keeps glTF's BRDF without its metal lobe and has
  // punctual lights alone, the box with a spot lamp has lights of both kinds, and the textured
  // box fills the slots of a Blender export (base colour, normal) and then the others; between them
  // each of the constants below is on in one case and off in another. The light selection is
  // the render's: power everywhere but in two cases, which select lamps.gltf's lights and the
  // box's two kinds by solid angle (its constant on).
  struct Case {
    const char* asset;
    bool withoutMetal = false;
    bool solidAngle = false;
    bool baked = false;  // its meshes placed once baked into one instance, as the renderer does
    bool skyMap = false;  // lit by the assets' sky map instead of its own sky
    bool spotLamp = false;  // the project's box with a spot lamp (boxWithSpotLamp)
    // The textured box (texturedBoxFilling) with these slots filled, where there are any.
    std::vector<int Material::*> textures;
  };
  std::vector<SceneFeatures> covered;
  for (const Case& c : {Case{.asset = "cornell-box.gltf", .baked = true}, Case{.asset = "materials.gltf"},
                       Case{.asset = "sky-spheres.gltf", .skyMap = true},
                       Case{.asset = "lamps.gltf", .withoutMetal = true},
                       Case{.asset = "lamps.gltf", .solidAngle = true},
                       Case{.asset = "cornell-box.gltf", .spotLamp = true},
                       Case{.asset = "cornell-box.gltf", .solidAngle = true, .spotLamp = true},
                       // The slots a Blender export fills, then the others.
                       Case{.asset = "cornell-box.gltf",
                            .textures = {&Material::baseColorTexture, &Material::normalTexture}},
                       Case{.asset = "cornell-box.gltf",
                            .textures = {&Material::metallicRoughnessTexture, &Material::emissiveTexture,
                                         &Material::specularTexture, &Material::specularColorTexture,
                                         &Material::sheenColorTexture, &Material::sheenRoughnessTexture,
                                         &Material::clearcoatTexture, &Material::clearcoatRoughnessTexture,
                                         &Material::clearcoatNormalTexture}}}) {
    SCOPED_TRACE(std::string(c.asset) + (c.spotLamp ? " with a spot lamp" : "") +
                 (!c.textures.empty() ? ", textured (" + std::to_string(c.textures.size()) + " slots)" : "") +
                 (c.solidAngle ? ", by solid angle" : ""));
    Scene scene = !c.textures.empty() ? texturedBoxFilling(c.textures) : c.spotLamp ? boxWithSpotLamp() : assetScene(c.asset);
    if (c.baked) scene = bakeSingleUseMeshes(scene);
    if (c.skyMap) scene.sky = assetSkyMap();
    GpuScene packed = packScene(scene);
    if (c.withoutMetal) removeMetalness(packed);
    covered.push_back(packed.features());
    const StageBuild specialized{.specialize = true, .withoutMetal = c.withoutMetal, .solidAngle = c.solidAngle};
    StageBuild everything = specialized;
    everything.specialize = false;
    expectSameBitForBit(renderVulkan(scene, specialized), renderVulkan(scene, everything));
    // OpenCL builds a program per scene with what it lacks defined false (prelude_cl.h).
    expectSameBitForBit(renderOpenCl(scene, specialized), renderOpenCl(scene, everything));
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
  EXPECT_TRUE(both(&SceneFeatures::instanced));
  EXPECT_TRUE(both(&SceneFeatures::planes));
  EXPECT_TRUE(both(&SceneFeatures::spheres));
  EXPECT_TRUE(both(&SceneFeatures::skyMap));
  EXPECT_TRUE(both(&SceneFeatures::punctual));
  for (const auto& [name, feature] : kTextureFeatures) EXPECT_TRUE(both(feature)) << name;
}

TEST(Samplers, StagesSpecializedToTheRendersSamplerMakeTheSameImageBitForBit) {
  // Vulkan compiles the independent sampler only into the stages of a render that draws from
  // it (WP_RENDER_INDEPENDENT_SAMPLER): bit for bit, since the draws are the same code either
  // way. A Sobol render's stages that kept only the independent sampler, or the reverse, would
  // draw other numbers and differ from the stages built with both.
  Scene box = bakeSingleUseMeshes(assetScene("cornell-box.gltf"));
  for (const SamplerKind sampler : {SamplerKind::Sobol, SamplerKind::Independent}) {
    SCOPED_TRACE(sampler == SamplerKind::Sobol ? "sobol" : "independent");
    expectSameBitForBit(renderVulkan(box, {.specialize = true, .sampler = sampler}),
                        renderVulkan(box, {.specialize = false, .sampler = sampler}));
  }
  EXPECT_FALSE(renderVulkan(box, {.sampler = SamplerKind::Sobol}).sum ==
               renderVulkan(box, {.sampler = SamplerKind::Independent}).sum)
      << "the two samplers drew the same numbers";
}

// Whether any entry of `layer` is not zero.
bool anyNonZero(const std::vector<glm::vec4>& layer) {
  for (const glm::vec4& v : layer)
    if (v != glm::vec4(0.0f)) return true;
  return false;
}

TEST(FeaturePasses, ARenderWithoutThemHasTheSameRadianceBitForBitAndNoFeatureSums) {
  // Bit for bit: leaving the passes out may only remove work whose results no radiance
  // depends on, the features' writes and sums and the last vertex's ray that a path seen
  // in perfect mirrors traces for its features alone. lamps.gltf with its gold made a perfect
  // mirror, at most two bounces: lit by lamps under a black sky, so that ray finds nothing
  // else; materials.gltf: smooth metals and glass under an emissive panel. Vulkan's stages
  // built without the passes' code and with it (the parameter tested as the stages run, as
  // OpenCL does), and PoCL's.
  Scene mirrors = assetScene("lamps.gltf");
  for (Material& m : mirrors.materials)
    if (m.metallic > 0.0f) m.roughness = 0.0f;
  struct Case {
    const char* name;
    const Scene scene;
    uint32_t maxBounces;
  };
  for (const Case& c : {Case{"lamps.gltf, mirrors", mirrors, 2}, Case{"materials.gltf", assetScene("materials.gltf"), 8}}) {
    SCOPED_TRACE(c.name);
    StageBuild with{.maxBounces = c.maxBounces};
    StageBuild without = with;
    without.featurePasses = false;
    StageBuild withEverything = with, withoutEverything = without;
    withEverything.specialize = withoutEverything.specialize = false;
    const std::pair<Accumulation, Accumulation> renders[] = {
        {renderVulkan(c.scene, with), renderVulkan(c.scene, without)},
        {renderVulkan(c.scene, withEverything), renderVulkan(c.scene, withoutEverything)},
        {renderOpenCl(c.scene, with), renderOpenCl(c.scene, without)}};
    for (const auto& [kept, left] : renders) {
      EXPECT_TRUE(anyNonZero(kept.sum)) << "the render is black";
      EXPECT_TRUE(kept.sum == left.sum) << "the radiance differs";
      EXPECT_TRUE(kept.sumSquares == left.sumSquares) << "the radiance's squares differ";
      EXPECT_TRUE(anyNonZero(kept.albedoDepth) && anyNonZero(kept.normal)) << "no features where kept";
      EXPECT_FALSE(anyNonZero(left.albedoDepth) || anyNonZero(left.normal)) << "features recorded where left out";
    }
  }
}

TEST(FeaturePasses, AreRecordedForAnExrThatKeepsSome) {
  const PassSelection all, none{false, false, false}, depthOnly{false, false, true};
  EXPECT_TRUE(outputKeepsFeaturePasses("out.exr", all));
  EXPECT_TRUE(outputKeepsFeaturePasses("OUT.EXR", depthOnly));
  EXPECT_FALSE(outputKeepsFeaturePasses("out.exr", none));
  EXPECT_FALSE(outputKeepsFeaturePasses("out.png", all));
  EXPECT_FALSE(outputKeepsFeaturePasses("frame_####.png", all));
}

// A scene of deep trees under a lamp: a soup of 4000 random triangles, whose bottom level
// needs several times the box's stack entries, in 30 random places (a top level of some
// depth), and an emissive quad over them.
Scene deepTreesScene() {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  auto point = [&] { return glm::vec3(unit(random), unit(random), unit(random)); };
  Scene scene;
  scene.materials.resize(2);
  for (Material& m : scene.materials) m.bsdf = Material::Bsdf::Lambert;
  scene.materials[1].emission = glm::vec3(8.0f);
  scene.materials[1].doubleSided = true;
  Mesh soup;
  for (int i = 0; i < 4000; ++i) {
    const glm::vec3 center = point();
    for (int k = 0; k < 3; ++k) soup.positions.push_back(center + 0.05f * point());
  }
  Mesh lamp;
  lamp.positions = {{-4, 6, -4}, {4, 6, -4}, {4, 6, 4}, {-4, 6, 4}};
  lamp.indices = {0, 1, 2, 0, 2, 3};
  lamp.materials = {1, 1};
  for (uint32_t v = 0; v < soup.positions.size(); ++v) soup.indices.push_back(v);
  soup.materials.assign(soup.triangleCount(), 0);
  scene.meshes = {soup, lamp};
  for (int i = 0; i < 30; ++i) {
    const glm::mat4 place = glm::translate(glm::mat4(1.0f), 3.0f * point());
    scene.instances.push_back({0, glm::rotate(place, 3.0f * unit(random), glm::normalize(point()))});
  }
  scene.instances.push_back({1, glm::mat4(1.0f)});
  return scene;
}

TEST(TraversalStacks, InWorkgroupMemoryMakeTheSameImageBitForBit) {
  // The stages specialized to the scene keep the stacks in workgroup memory, each invocation's
  // entries beside the others' and sized to the scene's trees (GpuScene::stackNeeds); with
  // every feature, in each invocation's own arrays, as C++ and OpenCL do. Bit for bit: the
  // same pushes and pops in another memory. A stack sized too small would overwrite another
  // invocation's entries, and the images would differ.
  const Scene scene = deepTreesScene();
  const TraversalStackNeeds needs = packScene(scene).stackNeeds();
  EXPECT_GE(needs.bottomLevel, 3 * packedAsset("cornell-box.gltf").stackNeeds().bottomLevel);
  EXPECT_GE(needs.topLevel, 10u);
  StackPlacement inWorkgroup, ownArrays;
  expectSameBitForBit(renderVulkan(scene, {.specialize = true, .placedStacks = &inWorkgroup}),
                      renderVulkan(scene, {.specialize = false, .placedStacks = &ownArrays}));
  EXPECT_TRUE(inWorkgroup.inWorkgroupMemory);
  EXPECT_GE(inWorkgroup.topLevelEntries, needs.topLevel);
  EXPECT_GE(inWorkgroup.bottomLevelEntries, needs.bottomLevel);
  EXPECT_FALSE(ownArrays.inWorkgroupMemory);
}

}  // namespace
}  // namespace wp::test
