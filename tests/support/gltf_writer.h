// Writes small glTF scenes (embedded buffer) for end-to-end tests.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace wp::test {

struct TestMaterial {
  glm::vec3 baseColor{1.0f};
  glm::vec3 emission{0.0f};  // written as emissiveFactor / max * KHR_materials_emissive_strength
  bool doubleSided = false;
  bool lambert = true;  // extras.wavepath.bsdf = "lambert"; false: the glTF material below
  float metallic = 0.0f;
  float roughness = 1.0f;
  float ior = 1.5f;           // KHR_materials_ior, written when not 1.5
  float transmission = 0.0f;  // KHR_materials_transmission, written when > 0
  glm::vec3 attenuationColor{1.0f};
  float attenuationDistance = 0.0f;  // KHR_materials_volume, written when > 0
  // More of the material's extensions, written as given: "\"KHR_materials_sheen\": {...}".
  std::string moreExtensions;
};

struct TestMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // glTF NORMAL, written when not empty
  std::vector<uint32_t> indices;
  int material = 0;
  glm::vec3 translation{0.0f};
};

struct TestCamera {
  glm::vec3 position{0.0f};
  float yawDegrees = 0.0f;  // rotation about +y; 0 looks down -z
  float yfovRadians = 0.8f;
};

struct TestScene {
  std::vector<TestMaterial> materials;
  std::vector<TestMesh> meshes;
  TestCamera camera;
  bool withCamera = true;  // false: the file has no camera (wavepath frames it itself)
};

// Standard base64 (RFC 4648) of `bytes`, for data: URIs.
std::string base64(const std::vector<uint8_t>& bytes);

// Writes `scene` as a .gltf file with one base64 buffer; returns the path.
std::filesystem::path writeGltf(const TestScene& scene, const std::filesystem::path& file);

// A closed icosphere of the given radius, `subdivisions` times refined, wound outwards.
TestMesh icosphere(float radius, int subdivisions);

}  // namespace wp::test
