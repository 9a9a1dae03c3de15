// End-to-end renders of each material kind on both backends (Vulkan under validation): MIS,
// NEE-only and BSDF-only must agree in mean radiance, and so must the switches that keep
// the estimator unbiased.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "support/gltf_writer.h"
#include "support/image_stats.h"
#include "support/render_exr.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

struct MaterialCase {
  const char* name;
  TestMaterial material;
  // Samples per pixel: NEE alone finds light through rough glass only from inside it, so
  // the glass cases need more samples to get the noise well below the signal; so does NEE
  // alone on a glossy coat, which reflects the light into the floor's dark channels.
  int spp = 96;
  // A coarse sphere with vertex normals (smooth shading) instead of a finer flat one.
  bool smoothShaded = false;
};

void PrintTo(const MaterialCase& c, std::ostream* os) { *os << c.name; }

TestMaterial gltfMaterial(glm::vec3 base, float metallic, float roughness, float transmission = 0.0f) {
  TestMaterial m;
  m.lambert = false;
  m.baseColor = base;
  m.metallic = metallic;
  m.roughness = roughness;
  m.transmission = transmission;
  return m;
}

TestMaterial absorbingGlass() {
  TestMaterial m = gltfMaterial(glm::vec3(1.0f), 0.0f, 0.0f, 1.0f);
  m.attenuationColor = glm::vec3(0.3f, 0.7f, 0.9f);
  m.attenuationDistance = 0.4f;
  return m;
}

// A glTF material with more extensions (KHR_materials_specular, _sheen, _clearcoat).
TestMaterial withExtensions(TestMaterial m, const char* extensions) {
  m.moreExtensions = extensions;
  return m;
}

// Smooth (roughness 0) lobes are delta lobes: they cover the cases where light sampling
// must leave a direction to BSDF sampling even in NEE-only mode.
const MaterialCase kCases[] = {
    {"RoughGold", gltfMaterial({1.0f, 0.78f, 0.34f}, 1.0f, 0.4f)},
    {"SmoothMirror", gltfMaterial({0.95f, 0.95f, 0.95f}, 1.0f, 0.0f)},
    {"RoughPlastic", gltfMaterial({0.8f, 0.1f, 0.1f}, 0.0f, 0.3f)},
    {"SmoothPlastic", gltfMaterial({0.1f, 0.3f, 0.8f}, 0.0f, 0.0f)},
    {"HalfMetal", gltfMaterial({0.9f, 0.6f, 0.3f}, 0.5f, 0.5f)},
    {"RoughGlass", gltfMaterial({1.0f, 1.0f, 1.0f}, 0.0f, 0.5f, 1.0f), 448},
    {"AbsorbingSmoothGlass", absorbingGlass(), 256},
    {"SmoothShadedPlastic", gltfMaterial({0.8f, 0.1f, 0.1f}, 0.0f, 0.3f), 96, true},
    {"SmoothShadedGlass", gltfMaterial({1.0f, 1.0f, 1.0f}, 0.0f, 0.5f, 1.0f), 448, true},
    {"TintedSpecular",
     withExtensions(gltfMaterial({0.2f, 0.2f, 0.6f}, 0.0f, 0.3f),
                    R"("KHR_materials_specular": {"specularFactor": 0.7, "specularColorFactor": [1, 0.6, 0.2]})")},
    {"Sheen", withExtensions(gltfMaterial({0.1f, 0.1f, 0.4f}, 0.0f, 0.6f),
                             R"("KHR_materials_sheen": {"sheenColorFactor": [1, 0.8, 0.5], "sheenRoughnessFactor": 0.4})")},
    {"RoughClearcoat",
     withExtensions(gltfMaterial({0.8f, 0.1f, 0.1f}, 0.0f, 0.7f),
                    R"("KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatRoughnessFactor": 0.2})"),
     192},
    {"SmoothClearcoatOverMetal",
     withExtensions(gltfMaterial({0.9f, 0.6f, 0.3f}, 1.0f, 0.5f), R"("KHR_materials_clearcoat": {"clearcoatFactor": 0.8})"),
     96, true},
    // Lights the floor only through BSDF-sampled rays (it is no light for NEE): the same
    // weight 1 in every mode.
    {"Unlit", withExtensions(gltfMaterial({0.9f, 0.6f, 0.2f}, 0.0f, 0.5f), R"("KHR_materials_unlit": {})")},
};

// A sphere of the material on a grey Lambertian floor, lit by a large one-sided area light
// above (large, so the caustics under glass that only BSDF sampling finds are not too noisy).
std::filesystem::path writeScene(const MaterialCase& c) {
  TestScene scene;
  TestMaterial floor;
  floor.baseColor = glm::vec3(0.5f);
  floor.doubleSided = true;
  TestMaterial light;
  light.baseColor = glm::vec3(0.0f);
  light.emission = glm::vec3(6.0f);
  scene.materials = {floor, light, c.material};
  TestMesh ground;
  ground.positions = {{-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}};
  ground.indices = {0, 1, 2, 0, 2, 3};
  ground.material = 0;
  TestMesh lamp;  // wound to face down
  lamp.positions = {{-0.8f, 2.0f, -0.8f}, {0.8f, 2.0f, -0.8f}, {0.8f, 2.0f, 0.8f}, {-0.8f, 2.0f, 0.8f}};
  lamp.indices = {0, 1, 2, 0, 2, 3};
  lamp.material = 1;
  TestMesh ball = icosphere(0.5f, c.smoothShaded ? 1 : 3);
  if (c.smoothShaded) {
    for (const glm::vec3& p : ball.positions) ball.normals.push_back(glm::normalize(p));
  }
  ball.translation = glm::vec3(0.0f, 0.5f, 0.0f);
  ball.material = 2;
  scene.meshes = {ground, lamp, ball};
  scene.camera.position = glm::vec3(0.0f, 0.7f, 1.8f);
  scene.camera.yfovRadians = 0.7f;
  return writeGltf(scene, scratchDirectory(std::string("material-") + c.name) / (std::string(c.name) + ".gltf"));
}

class MaterialRender : public ::testing::TestWithParam<std::tuple<std::string, MaterialCase>> {};

TEST_P(MaterialRender, MisNeeAndBsdfSamplingAgreeInMeanRadiance) {
  const auto& [backend, c] = GetParam();
  std::filesystem::path scene = writeScene(c);
  std::vector<std::string> base = {"--width", "32", "--height", "32", "--spp", std::to_string(c.spp), "--max-depth", "6"};
  std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
      {"mis", {"--mode", "mis"}}, {"nee", {"--mode", "nee"}}, {"bsdf", {"--mode", "bsdf"}}};
  if (std::string(c.name) == "RoughGlass") {
    runs.push_back({"mis --widen-roughness", {"--mode", "mis", "--widen-roughness"}});
  }
  std::vector<ImageMean> means;
  std::vector<std::string> names;
  for (const auto& [name, flags] : runs) {
    std::vector<std::string> args = base;
    args.insert(args.end(), flags.begin(), flags.end());
    means.push_back(imageMean(renderExr(backend, scene, args)));
    names.push_back(name);
  }
  expectAgreement(means, names);
}

std::string caseName(const ::testing::TestParamInfo<std::tuple<std::string, MaterialCase>>& info) {
  return std::string(std::get<1>(info.param).name) + "_" + std::get<0>(info.param);
}

INSTANTIATE_TEST_SUITE_P(Materials, MaterialRender,
                         ::testing::Combine(::testing::Values(std::string("vulkan"), std::string("opencl")),
                                            ::testing::ValuesIn(kCases)),
                         caseName);

}  // namespace
}  // namespace wp::test
