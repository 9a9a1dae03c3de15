// The ray from a path's last vertex (sampleContinuation, integrator.h): traced only where a
// ray can find emission (GpuScene::emissionHittable), since that ray can collect nothing
// else (but the feature passes behind a perfect mirror). Where nothing can emit towards it,
// leaving it out must leave the image and its passes as they were, bit for bit, on both
// backends; where a surface emits, the ray must still bring its share.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "app/backend_factory.h"
#include "bvh/gpu_scene.h"
#include "render/wavefront.h"
#include "scene/environment_map.h"
#include "scene/gltf_loader.h"
#include "support/asset_scene.h"
#include "support/same_accumulation.h"

namespace wp::test {
namespace {

// An emissive material that no surface has: it makes emission hittable as far as
// emissionHittable can tell, and changes nothing else (the light table comes from the
// surfaces, and the stages' features from the materials the surfaces have).
GpuScene withUnusedEmitter(GpuScene scene) {
  gpu::GpuMaterial emitter = scene.materials.front();
  emitter.emission = glm::vec4(1.0f, 1.0f, 1.0f, emitter.emission.w);
  scene.materials.push_back(emitter);
  return scene;
}

struct Render {
  Accumulation accumulation;
  RenderStats stats;
};

Render render(const std::string& backendName, const Scene& scene, const GpuScene& gpuScene, uint32_t maxBounces,
              IntegratorMode mode = IntegratorMode::Mis, uint32_t samplesPerPixel = 4) {
  const BackendChoice choice{backendName, -1, true, "readback"};
  std::unique_ptr<Backend> backend = createBackend(choice);
  RenderSettings settings;
  settings.width = 48;
  settings.height = 32;
  settings.samplesPerPixel = samplesPerPixel;
  settings.maxBounces = maxBounces;
  settings.mode = mode;
  WavefrontRenderer renderer(*backend, scene, gpuScene, settings);
  Render r;
  r.stats = renderer.render(nullptr);
  checkValidation(choice);
  r.accumulation = backend->readAccumulation();
  return r;
}

TEST(EmissionHittable, IsWhatASurfaceOrTheSkyCanEmit) {
  // Lamps alone, no sky (the loader gives a lit scene none): nothing a ray can hit emits.
  const GpuScene lamps = packScene(assetScene("lamps.gltf"));
  EXPECT_FALSE(lamps.emissionHittable());
  EXPECT_TRUE(withUnusedEmitter(lamps).emissionHittable());
  // The box's ceiling light emits.
  EXPECT_TRUE(packScene(assetScene("cornell-box.gltf")).emissionHittable());
  // A sky: bright, then black by its intensity.
  Scene lit = assetScene("lamps.gltf");
  lit.sky = makeEnvironmentMap(1, 1, {glm::vec3(0.2f, 0.3f, 0.4f)});
  EXPECT_TRUE(packScene(lit).emissionHittable());
  lit.skyIntensity = 0.0f;
  EXPECT_FALSE(packScene(lit).emissionHittable());
}

class LastVertexRay : public ::testing::TestWithParam<std::string> {};

TEST_P(LastVertexRay, IsNotTracedWhereNothingCanEmitAndTheImageIsTheSame) {
  // lamps.gltf: three lamps, no emissive surface, no sky. Bit for bit, not within a tolerance:
  // the paths draw the same numbers either way (a path's vertices each have their own), and
  // the ray left out would have added exactly 0. Direct light alone (max depth 0), where
  // every camera ray's vertex is the last, and with bounces. Then with its gold slab a perfect
  // mirror: a camera ray that meets it takes its feature passes (albedo, normal) from what
  // the mirror shows, at the next vertex, so that ray is still traced at depth 0.
  for (bool mirror : {false, true}) {
    Scene scene = assetScene("lamps.gltf");
    for (Material& m : scene.materials) {
      if (mirror && m.name == "gold") m.roughness = 0.0f;
    }
    const GpuScene gpuScene = packScene(scene);
    for (uint32_t maxBounces : {0u, 3u}) {
      SCOPED_TRACE(std::string(mirror ? "mirror, " : "") + "max bounces " + std::to_string(maxBounces));
      const Render spared = render(GetParam(), scene, gpuScene, maxBounces);
      const Render traced = render(GetParam(), scene, withUnusedEmitter(gpuScene), maxBounces);
      expectSameBitForBit(spared.accumulation, traced.accumulation);
      EXPECT_LT(spared.stats.extensionRays, traced.stats.extensionRays);
      EXPECT_EQ(spared.stats.shadowRays, traced.stats.shadowRays);
      if (maxBounces == 0 && !mirror) {
        EXPECT_EQ(spared.stats.extensionRays, spared.stats.samples);  // the camera rays alone
      } else if (maxBounces == 0) {
        EXPECT_GT(spared.stats.extensionRays, spared.stats.samples);  // and the mirror's
      }
    }
  }
}

// The image's mean radiance, over every channel.
double meanRadiance(const Accumulation& a) {
  double radiance = 0.0, samples = 0.0;
  for (const glm::vec4& s : a.sum) {
    radiance += (s.x + s.y + s.z) / 3.0;
    samples += s.w;
  }
  return radiance / samples;
}

TEST_P(LastVertexRay, IsTracedWhereASurfaceEmits) {
  // The Cornell box's ceiling light, direct light alone (max depth 0). With MIS the last
  // vertex's ray is traced; with BSDF sampling alone all of the light on the walls comes by
  // it, and its mean must agree with light sampling's, which takes all of it by the light
  // sample. Without that ray the BSDF image keeps only the light seen straight on: 0.67 of
  // light sampling's mean. The tolerance, 5%, is for the BSDF estimator's noise: its mean was
  // 0.994 of light sampling's at these 49,152 paths, 1.05 at an eighth of them.
  const Scene scene = assetScene("cornell-box.gltf");
  const GpuScene gpuScene = packScene(scene);
  const Render mis = render(GetParam(), scene, gpuScene, 0, IntegratorMode::Mis);
  EXPECT_GT(mis.stats.extensionRays, mis.stats.samples);
  const Render bsdfSampled = render(GetParam(), scene, gpuScene, 0, IntegratorMode::BsdfOnly, 32);
  const Render lightSampled = render(GetParam(), scene, gpuScene, 0, IntegratorMode::NeeOnly, 32);
  EXPECT_NEAR(meanRadiance(bsdfSampled.accumulation) / meanRadiance(lightSampled.accumulation), 1.0, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Backends, LastVertexRay, ::testing::Values("vulkan", "opencl"));

}  // namespace
}  // namespace wp::test
