// Tests of glTF loading into wp::Scene: geometry, transforms, materials, cameras, shapes,
// every error path, and the shipped Cornell box.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <stb_image_write.h>

#include "core/error.h"
#include "scene/gltf_loader.h"

namespace {

namespace fs = std::filesystem;
using wp::loadScene;
using wp::Scene;

constexpr int kU8 = 5121;
constexpr int kU16 = 5123;
constexpr int kU32 = 5125;
constexpr int kFloat = 5126;

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t chunk = static_cast<uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) chunk |= static_cast<uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) chunk |= static_cast<uint8_t>(bytes[i + 2]);
    out += digits[(chunk >> 18) & 63];
    out += digits[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[chunk & 63] : '=';
  }
  return out;
}

template <typename T>
std::string bytesOf(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// Builds the buffer, bufferViews and accessors of a small glTF file; the test writes the
// rest (meshes, nodes, ...) as JSON. Accessors are numbered 0, 1, ... in the order added.
class GltfFile {
public:
  int view(const std::string& bytes, size_t byteStride = 0) {
    while (blob_.size() % 4 != 0) blob_ += '\0';
    views_ += std::string(views_.empty() ? "" : ",") + R"({"buffer":0,"byteOffset":)" + std::to_string(blob_.size()) +
              R"(,"byteLength":)" + std::to_string(bytes.size()) +
              (byteStride ? R"(,"byteStride":)" + std::to_string(byteStride) : "") + "}";
    blob_ += bytes;
    return viewCount_++;
  }

  int accessor(int view, size_t byteOffset, int componentType, size_t count, const char* type) {
    accessors_ += std::string(accessors_.empty() ? "" : ",") + R"({"bufferView":)" + std::to_string(view) +
                  R"(,"byteOffset":)" + std::to_string(byteOffset) + R"(,"componentType":)" +
                  std::to_string(componentType) + R"(,"count":)" + std::to_string(count) + R"(,"type":")" + type +
                  "\"}";
    return accessorCount_++;
  }

  int positions(const std::vector<glm::vec3>& p) {
    return accessor(view(bytesOf(p)), 0, kFloat, p.size(), "VEC3");
  }

  int indices(const std::vector<uint32_t>& values, int componentType = kU32) {
    std::string bytes;
    for (uint32_t v : values) {
      if (componentType == kU8) bytes += bytesOf(std::vector<uint8_t>{static_cast<uint8_t>(v)});
      if (componentType == kU16) bytes += bytesOf(std::vector<uint16_t>{static_cast<uint16_t>(v)});
      if (componentType == kU32) bytes += bytesOf(std::vector<uint32_t>{v});
    }
    return accessor(view(bytes), 0, componentType, values.size(), "SCALAR");
  }

  // A .gltf document with the buffer as a data: URI, or as `uri` when given.
  std::string json(const std::string& rest, const std::string& uri = "") const {
    return document(rest, R"({"byteLength":)" + std::to_string(blob_.size()) + R"(,"uri":")" +
                              (uri.empty() ? "data:application/octet-stream;base64," + base64(blob_) : uri) + "\"}");
  }

  // A .glb: 12-byte header, JSON chunk padded with spaces, BIN chunk padded with zeros.
  std::string glb(const std::string& rest) const {
    std::string json = document(rest, R"({"byteLength":)" + std::to_string(blob_.size()) + "}");
    while (json.size() % 4 != 0) json += ' ';
    std::string bin = blob_;
    while (bin.size() % 4 != 0) bin += '\0';
    const auto u32 = [](size_t v) { return bytesOf(std::vector<uint32_t>{static_cast<uint32_t>(v)}); };
    return "glTF" + u32(2) + u32(12 + 8 + json.size() + 8 + bin.size()) + u32(json.size()) + "JSON" + json +
           u32(bin.size()) + "BIN" + std::string(1, '\0') + bin;
  }

  const std::string& blob() const { return blob_; }

private:
  std::string document(const std::string& rest, const std::string& buffer) const {
    return R"({"asset":{"version":"2.0"},"buffers":[)" + buffer + R"(],"bufferViews":[)" + views_ +
           R"(],"accessors":[)" + accessors_ + "]" + (rest.empty() ? "" : "," + rest) + "}";
  }

  std::string blob_;
  std::string views_;
  std::string accessors_;
  int viewCount_ = 0;
  int accessorCount_ = 0;
};

// One triangle in the z = 0 plane, as accessor 0.
GltfFile triangleFile() {
  GltfFile file;
  file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  return file;
}

// A scene with one node showing mesh 0 (a single primitive on accessor 0).
const std::string kOneTriangle =
    R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])";

glm::vec3 toWorld(const Scene& scene, size_t instance, const glm::vec3& p) {
  const wp::MeshInstance& i = scene.instances.at(instance);
  return glm::vec3(i.objectToWorld * glm::vec4(p, 1.0f));
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

class SceneTest : public ::testing::Test {
protected:
  void SetUp() override {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() / ("wavepath_scene_test_" + std::to_string(getpid()) + "_" + test);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& content) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }

  // Loads a .gltf written from `json`, returning the scene and what was printed on stderr.
  Scene load(const std::string& json, std::string* printed = nullptr, const wp::LoadOptions& options = {}) {
    const fs::path path = write("scene.gltf", json);
    ::testing::internal::CaptureStderr();
    Scene scene;
    try {
      scene = loadScene(path, options);
    } catch (...) {
      ::testing::internal::GetCapturedStderr();
      throw;
    }
    const std::string out = ::testing::internal::GetCapturedStderr();
    if (printed) *printed = out;
    return scene;
  }

  // The message of the wp::Error that loading `path` throws, checked to be one line naming
  // the file.
  std::string errorOf(const fs::path& path, const wp::LoadOptions& options = {}) {
    ::testing::internal::CaptureStderr();
    std::string message = "(no error)";
    try {
      loadScene(path, options);
    } catch (const wp::Error& e) {
      message = e.what();
    }
    ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind(path.string() + ":", 0), 0u) << message;
    return message;
  }

  std::string errorOfJson(const std::string& json, const wp::LoadOptions& options = {}) {
    return errorOf(write("scene.gltf", json), options);
  }

  fs::path dir_;
};

// --- geometry and transforms ---

TEST_F(SceneTest, ComposesTrsAndMatrixTransformsDownTheHierarchy) {
  GltfFile file = triangleFile();
  // Node 0: T(1,2,3) R(90 degrees about z) S(2); its child node 1: matrix = translate(1,0,0).
  const Scene scene = load(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"translation":[1,2,3],"rotation":[0,0,0.70710678,0.70710678],"scale":[2,2,2],"children":[1]},
             {"matrix":[1,0,0,0, 0,1,0,0, 0,0,1,0, 1,0,0,1],"mesh":0}],
    "scenes":[{"nodes":[0]}])"));
  ASSERT_EQ(scene.instances.size(), 1u);
  // (1,0,0) -> child (2,0,0) -> scale (4,0,0) -> rotate (0,4,0) -> translate (1,6,3).
  expectNear(toWorld(scene, 0, {1, 0, 0}), {1, 6, 3});
  // (0,1,0) -> child (1,1,0) -> scale (2,2,0) -> rotate (-2,2,0) -> translate (-1,4,3).
  expectNear(toWorld(scene, 0, {0, 1, 0}), {-1, 4, 3});
}

TEST_F(SceneTest, UsesTheDefaultSceneOrAllRootNodesWithoutScenes) {
  GltfFile file = triangleFile();
  const Scene chosen = load(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0,"translation":[5,0,0]},{"mesh":0,"translation":[7,0,0]}],
    "scenes":[{"nodes":[0]},{"nodes":[1]}],"scene":1)"));
  ASSERT_EQ(chosen.instances.size(), 1u);
  expectNear(toWorld(chosen, 0, {0, 0, 0}), {7, 0, 0});

  const Scene roots = load(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0,"children":[1]},{"mesh":0,"translation":[0,1,0]},{"mesh":0}])"));
  EXPECT_EQ(roots.instances.size(), 3u);
}

class IndexTypeTest : public SceneTest, public ::testing::WithParamInterface<int> {};

TEST_P(IndexTypeTest, ReadsIndices) {
  GltfFile file;
  file.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  file.indices({0, 1, 2, 0, 2, 3}, GetParam());
  const Scene scene = load(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(scene.meshes[0].positions.size(), 4u);
}

INSTANTIATE_TEST_SUITE_P(UnsignedByteShortInt, IndexTypeTest, ::testing::Values(kU8, kU16, kU32));

TEST_F(SceneTest, NonIndexedPrimitivesUseTheVerticesInOrder) {
  GltfFile file;
  file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
  const Scene scene = load(file.json(kOneTriangle));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(scene.meshes[0].triangleCount(), 2u);
}

TEST_F(SceneTest, HonoursByteStrideAndBothByteOffsets) {
  GltfFile file;
  file.view(std::string(12, 'x'));  // so that the positions' view starts at byte 12
  // Each 16-byte element: one float of padding, then x, y, z; the accessor skips the padding.
  const std::vector<float> interleaved = {-1, 0, 0, 0, -1, 1, 0, 0, -1, 0, 1, 0};
  const int view = file.view(bytesOf(interleaved), 16);
  file.accessor(view, 4, kFloat, 3, "VEC3");
  const Scene scene = load(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.meshes[0].positions.size(), 3u);
  expectNear(scene.meshes[0].positions[0], {0, 0, 0});
  expectNear(scene.meshes[0].positions[1], {1, 0, 0});
  expectNear(scene.meshes[0].positions[2], {0, 1, 0});
}

TEST_F(SceneTest, LoadsBinaryGlb) {
  GltfFile file;
  file.positions({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}});
  file.indices({0, 1, 2}, kU16);
  const fs::path path = write("scene.glb", file.glb(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
    "nodes":[{"mesh":0,"translation":[0,0,1]}],"scenes":[{"nodes":[0]}])"));
  ::testing::internal::CaptureStderr();
  const Scene scene = loadScene(path);
  ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2}));
  expectNear(toWorld(scene, 0, scene.meshes[0].positions[1]), {2, 0, 1});
}

TEST_F(SceneTest, LoadsAnExternalBufferBesideTheFile) {
  GltfFile file = triangleFile();
  write("triangle.bin", file.blob());
  const Scene scene = load(file.json(kOneTriangle, "triangle.bin"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  expectNear(scene.meshes[0].positions[2], {0, 1, 0});
}

TEST_F(SceneTest, AMeshUsedByTwoNodesIsOneMeshWithTwoInstances) {
  GltfFile file = triangleFile();
  const Scene scene = load(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0},{"mesh":0,"translation":[0,0,-3]}],"scenes":[{"nodes":[0,1]}])"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_EQ(scene.instances[0].mesh, 0u);
  EXPECT_EQ(scene.instances[1].mesh, 0u);
  expectNear(toWorld(scene, 1, {1, 0, 0}), {1, 0, -3});
}

TEST_F(SceneTest, MergesPrimitivesWithPerTriangleMaterials) {
  GltfFile file;
  file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  file.positions({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
  const Scene scene = load(file.json(R"(
    "materials":[{"name":"a"},{"name":"b"}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":1},
                             {"attributes":{"POSITION":1},"material":0},
                             {"attributes":{"POSITION":0},"material":1}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const wp::Mesh& mesh = scene.meshes[0];
  EXPECT_EQ(mesh.positions.size(), 6u);  // primitives sharing accessor 0 share its vertices
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 0, 1, 2}));
  EXPECT_EQ(mesh.materials, (std::vector<uint32_t>{1, 0, 1}));
}

TEST_F(SceneTest, SkipsPointsAndLinesWithOneWarningPerMesh) {
  GltfFile file = triangleFile();
  std::string printed;
  const Scene scene = load(file.json(R"(
    "meshes":[{"name":"Wire","primitives":[{"attributes":{"POSITION":0},"mode":0},
                                           {"attributes":{"POSITION":0},"mode":1},
                                           {"attributes":{"POSITION":0},"mode":4}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"),
                           &printed);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].triangleCount(), 1u);
  EXPECT_NE(printed.find("wavepath: warning: "), std::string::npos) << printed;
  EXPECT_NE(printed.find("mesh 0 'Wire': skipped primitives 0 (POINTS), 1 (LINES)"), std::string::npos) << printed;
  EXPECT_EQ(printed.find("warning", printed.find("warning") + 1), std::string::npos) << printed;
}

TEST_F(SceneTest, ConvertsStripsAndFansToTriangles) {
  GltfFile file;
  file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}});
  const Scene scene = load(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":5},{"attributes":{"POSITION":0},"mode":6}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  // Strip: (0,1,2) (1,3,2) (2,3,4), every other triangle flipped to keep the winding.
  // Fan: (1,2,0) (2,3,0) (3,4,0).
  EXPECT_EQ(scene.meshes[0].indices,
            (std::vector<uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4, 1, 2, 0, 2, 3, 0, 3, 4, 0}));
}

// --- materials ---

TEST_F(SceneTest, ConvertsMaterialsWithEmissiveStrength) {
  GltfFile file = triangleFile();
  const Scene scene = load(file.json(R"(
    "extensionsUsed":["KHR_materials_emissive_strength"],
    "materials":[{"name":"paint","doubleSided":true,"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.25,0.125,0.75]}},
                 {"name":"lamp","emissiveFactor":[1,0.5,0.25],
                  "extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":8}}}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0},{"attributes":{"POSITION":0},"material":1}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  ASSERT_EQ(scene.materials.size(), 2u);  // no default material: every primitive names one
  const wp::Material& paint = scene.materials[0];
  EXPECT_EQ(paint.name, "paint");
  expectNear(paint.baseColor, {0.5f, 0.25f, 0.125f});
  EXPECT_FLOAT_EQ(paint.alpha, 0.75f);
  EXPECT_TRUE(paint.doubleSided);
  EXPECT_FALSE(paint.isEmissive());
  const wp::Material& lamp = scene.materials[1];
  expectNear(lamp.emission, {8.0f, 4.0f, 2.0f});
  expectNear(lamp.baseColor, {1, 1, 1});
  EXPECT_FALSE(lamp.doubleSided);
  EXPECT_EQ(scene.sky.width, 0u);
}

TEST_F(SceneTest, ConvertsMetallicRoughnessIorTransmissionVolumeAndLambert) {
  GltfFile file = triangleFile();
  const Scene scene = load(file.json(R"(
    "extensionsUsed":["KHR_materials_ior","KHR_materials_transmission","KHR_materials_volume"],
    "extensionsRequired":["KHR_materials_transmission"],
    "materials":[{"name":"default"},
                 {"name":"glass","pbrMetallicRoughness":{"metallicFactor":0,"roughnessFactor":0.25},
                  "extensions":{"KHR_materials_ior":{"ior":1.33},"KHR_materials_transmission":{"transmissionFactor":0.9},
                                "KHR_materials_volume":{"attenuationColor":[0.5,0.75,1],"attenuationDistance":2}}},
                 {"name":"clay","pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1],"metallicFactor":2},
                  "extras":{"wavepath":{"bsdf":"lambert"}}},
                 {"name":"seed","extras":{"wavepath":{"diffuse":"disney"}}},
                 {"name":"plain","extras":{"wavepath":{"diffuse":"lambert"}}}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0},{"attributes":{"POSITION":0},"material":1},
                             {"attributes":{"POSITION":0},"material":2},{"attributes":{"POSITION":0},"material":3},
                             {"attributes":{"POSITION":0},"material":4}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  ASSERT_EQ(scene.materials.size(), 5u);
  const wp::Material& fallback = scene.materials[0];  // glTF's defaults: a rough metal
  EXPECT_EQ(fallback.bsdf, wp::Material::Bsdf::Gltf);
  EXPECT_FLOAT_EQ(fallback.metallic, 1.0f);
  EXPECT_FLOAT_EQ(fallback.roughness, 1.0f);
  EXPECT_FLOAT_EQ(fallback.ior, 1.5f);
  EXPECT_FLOAT_EQ(fallback.transmission, 0.0f);
  EXPECT_EQ(fallback.attenuationDistance, std::numeric_limits<float>::max());
  const wp::Material& glass = scene.materials[1];
  EXPECT_FLOAT_EQ(glass.metallic, 0.0f);
  EXPECT_FLOAT_EQ(glass.roughness, 0.25f);
  EXPECT_FLOAT_EQ(glass.ior, 1.33f);
  EXPECT_FLOAT_EQ(glass.transmission, 0.9f);
  expectNear(glass.attenuationColor, {0.5f, 0.75f, 1.0f});
  EXPECT_FLOAT_EQ(glass.attenuationDistance, 2.0f);
  EXPECT_EQ(scene.materials[2].bsdf, wp::Material::Bsdf::Lambert);
  EXPECT_FLOAT_EQ(scene.materials[2].metallic, 1.0f);  // clamped to glTF's [0, 1]
  EXPECT_EQ(scene.materials[3].bsdf, wp::Material::Bsdf::GltfDisneyDiffuse);
  EXPECT_EQ(scene.materials[4].bsdf, wp::Material::Bsdf::Gltf);
}

TEST_F(SceneTest, ConvertsSpecularSheenClearcoatAndUnlit) {
  GltfFile file = triangleFile();
  const Scene scene = load(file.json(R"(
    "extensionsUsed":["KHR_materials_specular","KHR_materials_sheen","KHR_materials_clearcoat","KHR_materials_unlit"],
    "extensionsRequired":["KHR_materials_sheen","KHR_materials_unlit"],
    "materials":[{"name":"default"},
                 {"name":"layered","extensions":{
                    "KHR_materials_specular":{"specularFactor":0.25,"specularColorFactor":[2,0.5,0]},
                    "KHR_materials_sheen":{"sheenColorFactor":[0.5,0.25,1],"sheenRoughnessFactor":0.75},
                    "KHR_materials_clearcoat":{"clearcoatFactor":0.5,"clearcoatRoughnessFactor":0.125}}},
                 {"name":"flat","extensions":{"KHR_materials_unlit":{}}}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0},{"attributes":{"POSITION":0},"material":1},
                             {"attributes":{"POSITION":0},"material":2}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  ASSERT_EQ(scene.materials.size(), 3u);
  const wp::Material& fallback = scene.materials[0];  // no layers, white full specular
  EXPECT_FLOAT_EQ(fallback.specularWeight, 1.0f);
  expectNear(fallback.specularColor, {1, 1, 1});
  expectNear(fallback.sheenColor, {0, 0, 0});
  EXPECT_FLOAT_EQ(fallback.clearcoat, 0.0f);
  const wp::Material& layered = scene.materials[1];
  EXPECT_FLOAT_EQ(layered.specularWeight, 0.25f);
  expectNear(layered.specularColor, {2.0f, 0.5f, 0.0f});
  expectNear(layered.sheenColor, {0.5f, 0.25f, 1.0f});
  EXPECT_FLOAT_EQ(layered.sheenRoughness, 0.75f);
  EXPECT_FLOAT_EQ(layered.clearcoat, 0.5f);
  EXPECT_FLOAT_EQ(layered.clearcoatRoughness, 0.125f);
  EXPECT_EQ(layered.clearcoatNormalTexture, -1);
  EXPECT_EQ(layered.bsdf, wp::Material::Bsdf::Gltf);
  EXPECT_EQ(scene.materials[2].bsdf, wp::Material::Bsdf::Unlit);
}

// KHR_materials_variants: --variant NAME picks each primitive's mapped material; a primitive
// without a mapping for it, and every primitive without --variant, keeps its own.
TEST_F(SceneTest, MaterialVariantsPickMappedMaterials) {
  GltfFile file = triangleFile();
  const std::string json = file.json(R"(
    "extensionsUsed":["KHR_materials_variants"],
    "extensions":{"KHR_materials_variants":{"variants":[{"name":"red"},{"name":"blue"}]}},
    "materials":[{"name":"default"},{"name":"red"},{"name":"blue"}],
    "meshes":[{"primitives":[
      {"attributes":{"POSITION":0},"material":0,
       "extensions":{"KHR_materials_variants":{"mappings":[{"material":1,"variants":[0]},{"material":2,"variants":[1]}]}}},
      {"attributes":{"POSITION":0},"material":0,
       "extensions":{"KHR_materials_variants":{"mappings":[{"material":2,"variants":[1]}]}}}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])");
  const auto materialsOf = [&](const std::string& variant) {
    wp::LoadOptions options;
    options.variant = variant;
    const Scene scene = load(json, nullptr, options);
    return std::vector<uint32_t>(scene.meshes.at(0).materials);
  };
  EXPECT_EQ(materialsOf(""), (std::vector<uint32_t>{0, 0}));
  EXPECT_EQ(materialsOf("red"), (std::vector<uint32_t>{1, 0}));
  EXPECT_EQ(materialsOf("blue"), (std::vector<uint32_t>{2, 2}));
  wp::LoadOptions green;
  green.variant = "green";
  EXPECT_NE(errorOfJson(json, green)
                .find("--variant 'green' is not a KHR_materials_variants variant of the file (it has 'red', 'blue')"),
            std::string::npos);
}

TEST_F(SceneTest, RejectsMaterialExtensionValuesOutOfRange) {
  GltfFile file = triangleFile();
  auto errorOf = [&](const std::string& material) {
    return errorOfJson(file.json(R"("materials":[)" + material + R"(],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],
      "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  };
  EXPECT_NE(errorOf(R"({"extensions":{"KHR_materials_ior":{"ior":0.5}}})")
                .find("material 0: KHR_materials_ior.ior must be a number in [1, 10]; fix the material"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"extensions":{"KHR_materials_transmission":{"transmissionFactor":"all"}}})")
                .find("KHR_materials_transmission.transmissionFactor must be a number in [0, 1]"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"extensions":{"KHR_materials_volume":{"attenuationDistance":0}}})")
                .find("KHR_materials_volume.attenuationDistance must be a number > 0"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"extensions":{"KHR_materials_volume":{"attenuationColor":[1,2,1]}}})")
                .find("KHR_materials_volume.attenuationColor must be 3 numbers in [0, 1]"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"extensions":{"KHR_materials_sheen":{"sheenRoughnessFactor":1.5}}})")
                .find("material 0: KHR_materials_sheen.sheenRoughnessFactor must be a number in [0, 1]"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"extensions":{"KHR_materials_specular":{"specularColorFactor":[1,-1,1]}}})")
                .find("KHR_materials_specular.specularColorFactor must be 3 numbers in [0, 100]"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"extensions":{"KHR_materials_clearcoat":{"clearcoatNormalTexture":{"scale":2}}}})")
                .find("KHR_materials_clearcoat.clearcoatNormalTexture needs an integer \"index\""),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"extensions":{"KHR_materials_clearcoat":{"clearcoatTexture":{"index":7}}}})")
                .find("material 0"),
            std::string::npos);
  const std::string extrasError = R"(a material's extras.wavepath must be {"bsdf": "lambert"} or {"diffuse": )";
  EXPECT_NE(errorOf(R"({"extras":{"wavepath":{"bsdf":"phong"}}})").find(extrasError), std::string::npos);
  EXPECT_NE(errorOf(R"({"extras":{"wavepath":{"diffuse":"oren-nayar"}}})").find(extrasError), std::string::npos);
  EXPECT_NE(errorOf(R"({"extras":{"wavepath":{"bsdf":"lambert","diffuse":"disney"}}})").find(extrasError),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"extras":{"wavepath":{"difuse":"disney"}}})").find(extrasError), std::string::npos);
}

// glTF alphaMode: OPAQUE (the default) ignores alpha, MASK keeps its cutoff (default 0.5),
// BLEND; a mode glTF does not name, or a negative cutoff, is one error line.
TEST_F(SceneTest, ReadsAlphaModesAndCutoffs) {
  GltfFile file = triangleFile();
  auto json = [&](const std::string& materials) {
    return file.json(R"("materials":[)" + materials + R"(],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],
      "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])");
  };
  const Scene scene = load(json(R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.3]}},
      {"alphaMode":"MASK"}, {"alphaMode":"MASK","alphaCutoff":0.25}, {"alphaMode":"BLEND"})"));
  ASSERT_GE(scene.materials.size(), 4u);
  EXPECT_EQ(scene.materials[0].alphaMode, wp::Material::AlphaMode::Opaque);
  EXPECT_FLOAT_EQ(scene.materials[0].alpha, 0.3f);
  EXPECT_EQ(scene.materials[1].alphaMode, wp::Material::AlphaMode::Mask);
  EXPECT_FLOAT_EQ(scene.materials[1].alphaCutoff, 0.5f);
  EXPECT_FLOAT_EQ(scene.materials[2].alphaCutoff, 0.25f);
  EXPECT_EQ(scene.materials[3].alphaMode, wp::Material::AlphaMode::Blend);
  EXPECT_NE(errorOfJson(json(R"({"alphaMode":"CLIP"})")).find("material 0: alphaMode 'CLIP' is not OPAQUE, MASK or BLEND"),
            std::string::npos);
  EXPECT_NE(errorOfJson(json(R"({"alphaMode":"MASK","alphaCutoff":-1})")).find("alphaCutoff must be a finite number >= 0"),
            std::string::npos);
}

// --- vertex normals ---

// A primitive without NORMAL before one with: the mesh gets normals, zero (flat) for the
// first primitive's vertices, and unit length for the second's however they were stored.
TEST_F(SceneTest, ReadsVertexNormalsAndZeroFillsPrimitivesWithout) {
  GltfFile file;
  file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});            // accessor 0
  file.positions({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});            // accessor 1
  file.positions({{0, 0, 2}, {0.6f, 0, 0.8f}, {0, 0, 0}});      // accessor 2: NORMAL of 1
  const Scene scene = load(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}},{"attributes":{"POSITION":1,"NORMAL":2}}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const wp::Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.normals.size(), 6u);
  for (int i = 0; i < 3; ++i) expectNear(mesh.normals[i], {0, 0, 0});
  expectNear(mesh.normals[3], {0, 0, 1});
  expectNear(mesh.normals[4], {0.6f, 0, 0.8f});
  expectNear(mesh.normals[5], {0, 0, 0});  // zero stays zero: that vertex shades flat
  const std::string message = errorOfJson(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":3}}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  EXPECT_NE(message.find("NORMAL"), std::string::npos) << message;
}

// --- textures ---

// A 2x1 PNG: red, then blue with alpha 128.
std::string twoTexelPng() {
  const uint8_t rgba[] = {255, 0, 0, 255, 0, 0, 255, 128};
  std::string png;
  stbi_write_png_to_func([](void* out, void* data, int size) { static_cast<std::string*>(out)->append(static_cast<char*>(data), size); },
                         &png, 2, 1, 4, rgba, 8);
  return png;
}

const std::string kTexturedMaterial = R"(
    "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicRoughnessTexture":{"index":0}}}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],
    "samplers":[{"magFilter":9728,"wrapS":33071,"wrapT":33648}],
    "textures":[{"source":0,"sampler":0}],)";

void expectTwoTexelTextures(const Scene& scene) {
  ASSERT_EQ(scene.textures.size(), 2u);  // one sRGB (base colour), one linear
  const wp::Texture& base = scene.textures[static_cast<size_t>(scene.materials[0].baseColorTexture)];
  EXPECT_TRUE(base.srgb);
  EXPECT_FALSE(scene.textures[static_cast<size_t>(scene.materials[0].metallicRoughnessTexture)].srgb);
  EXPECT_EQ(base.width, 2u);
  EXPECT_EQ(base.height, 1u);
  EXPECT_EQ(base.rgba, (std::vector<uint32_t>{0xff0000ffu, 0x80ff0000u}));
  EXPECT_TRUE(base.nearest);
  EXPECT_EQ(base.wrapS, wp::Texture::Wrap::Clamp);
  EXPECT_EQ(base.wrapT, wp::Texture::Wrap::Mirror);
  ASSERT_EQ(scene.meshes[0].uvs.size(), 3u);
  expectNear(glm::vec3(scene.meshes[0].uvs[2], 0.0f), {0.0f, 1.0f, 0.0f});
}

TEST_F(SceneTest, ReadsTexturesFromDataUrisAndGlbBufferViews) {
  const std::string png = twoTexelPng();
  GltfFile file = triangleFile();
  file.accessor(file.view(bytesOf(std::vector<glm::vec2>{{0, 0}, {1, 0}, {0, 1}})), 0, kFloat, 3, "VEC2");
  expectTwoTexelTextures(load(file.json(kTexturedMaterial + R"("images":[{"uri":"data:image/png;base64,)" +
                                        base64(png) + R"("}])")));
  const int view = file.view(png);
  const fs::path glb = write("scene.glb", file.glb(kTexturedMaterial + R"("images":[{"bufferView":)" +
                                                   std::to_string(view) + R"(,"mimeType":"image/png"}])"));
  expectTwoTexelTextures(loadScene(glb));
}

TEST_F(SceneTest, ReadsVertexColorsOfEachEncoding) {
  GltfFile file = triangleFile();
  const std::vector<uint8_t> bytes = {255, 0, 51, 0, 102, 255, 0, 0, 0, 0, 255, 0};  // VEC3, stride 4
  const int u8 = file.accessor(file.view(bytesOf(bytes), 4), 0, kU8, 3, "VEC3");
  const int f32 = file.accessor(file.view(bytesOf(std::vector<glm::vec4>{{0.5f, 0.25f, 1, 0.5f}, {0, 0, 0, 1}, {1, 1, 1, 1}})), 0,
                                kFloat, 3, "VEC4");
  std::string json = file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0,"COLOR_0":)" + std::to_string(u8) + R"(}},
                             {"attributes":{"POSITION":0,"COLOR_0":)" + std::to_string(f32) + R"(}},
                             {"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])");
  // glTF requires "normalized" on integer colours; tinygltf's writer of this test leaves it out.
  const std::string needle = R"("componentType":5121)";
  json.replace(json.find(needle), needle.size(), needle + R"(,"normalized":true)");
  const Scene scene = load(json);
  const std::vector<glm::vec4>& colors = scene.meshes[0].colors;
  ASSERT_EQ(colors.size(), 9u);
  EXPECT_EQ(colors[0], glm::vec4(1.0f, 0.0f, 0.2f, 1.0f));
  EXPECT_EQ(colors[1], glm::vec4(0.4f, 1.0f, 0.0f, 1.0f));
  EXPECT_EQ(colors[3], glm::vec4(0.5f, 0.25f, 1.0f, 0.5f));
  EXPECT_EQ(colors[8], glm::vec4(1.0f));  // the primitive without COLOR_0: white
}

// TANGENT is read where a primitive has NORMAL too (glTF ignores it otherwise), made unit
// with a sign of exactly +-1, and zero for the vertices of primitives without it.
TEST_F(SceneTest, ReadsTangentsWithNormalsAndZeroFillsTheRest) {
  GltfFile file = triangleFile();                                    // accessor 0
  file.positions({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});                 // accessor 1: NORMAL
  const std::vector<glm::vec4> stored = {{2, 0, 0, 1}, {0, 0.5f, 0, -0.5f}, {0.6f, 0.8f, 0, 3}};
  const int tangents = file.accessor(file.view(bytesOf(stored)), 0, kFloat, 3, "VEC4");  // accessor 2
  file.positions({{0, 0, 2}, {1, 0, 2}, {0, 1, 2}});                 // accessor 3: another triangle
  file.positions({{0, 0, 3}, {1, 0, 3}, {0, 1, 3}});                 // accessor 4: and another
  const Scene scene = load(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1,"TANGENT":)" + std::to_string(tangents) + R"(}},
                             {"attributes":{"POSITION":3,"NORMAL":1}},
                             {"attributes":{"POSITION":4,"TANGENT":)" + std::to_string(tangents) + R"(}}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  const std::vector<glm::vec4>& t = scene.meshes[0].tangents;
  ASSERT_EQ(t.size(), 9u);
  EXPECT_EQ(t[0], glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(t[1], glm::vec4(0, 1, 0, -1));
  EXPECT_NEAR(glm::length(t[2] - glm::vec4(0.6f, 0.8f, 0, 1)), 0.0f, 1e-6f);
  for (size_t i = 3; i < 9; ++i) EXPECT_EQ(t[i], glm::vec4(0.0f)) << i;  // no TANGENT, or no NORMAL
  const std::string message = errorOfJson(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1,"TANGENT":1}}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  EXPECT_NE(message.find("TANGENT must be VEC4 of FLOAT or normalized BYTE or SHORT, not FLOAT VEC3"), std::string::npos) << message;
}

// emissiveTexture is an sRGB texture of the material, read without the warning about
// textures wavepath ignores; so is an occlusion texture, which a path tracer has no use for.
TEST_F(SceneTest, ReadsEmissiveTexturesAndLeavesOcclusionUnsaid) {
  GltfFile file = triangleFile();
  file.accessor(file.view(bytesOf(std::vector<glm::vec2>{{0, 0}, {1, 0}, {0, 1}})), 0, kFloat, 3, "VEC2");
  const std::string rest = R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],
    "textures":[{"source":0}],"images":[{"uri":"data:image/png;base64,)" + base64(twoTexelPng()) + R"("}],)";
  std::string printed;
  const std::string emissive = R"("materials":[{"emissiveFactor":[1,0.5,1],"emissiveTexture":{"index":0}}])";
  const Scene scene = load(file.json(rest + emissive), &printed);
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.materials[0].emissiveTexture, 0);
  EXPECT_TRUE(scene.textures[0].srgb);
  EXPECT_EQ(printed.find("ignores"), std::string::npos) << printed;
  const Scene occluded = load(file.json(rest + R"("materials":[{"occlusionTexture":{"index":0}}])"), &printed);
  EXPECT_TRUE(occluded.textures.empty());
  EXPECT_EQ(printed.find("ignores"), std::string::npos) << printed;
}

// texCoord and KHR_texture_transform: each slot gets its set (the transform's texCoord
// wins) and the matrix T(offset) R(rotation) S(scale); TEXCOORD_1 is read per vertex; a set
// past 1 is left out with a warning, a malformed transform is an error.
TEST_F(SceneTest, ReadsTexCoordSetsAndTextureTransforms) {
  GltfFile file = triangleFile();
  file.accessor(file.view(bytesOf(std::vector<glm::vec2>{{0, 0}, {1, 0}, {0, 1}})), 0, kFloat, 3, "VEC2");
  file.accessor(file.view(bytesOf(std::vector<glm::vec2>{{5, 6}, {7, 8}, {9, 10}})), 0, kFloat, 3, "VEC2");
  const std::string rest = R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1,"TEXCOORD_1":2},"material":0}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],
    "textures":[{"source":0}],"images":[{"uri":"data:image/png;base64,)" + base64(twoTexelPng()) + R"("}],)";
  const Scene scene = load(file.json(rest + R"("materials":[{
      "pbrMetallicRoughness":{"baseColorTexture":{"index":0,"texCoord":1},
        "metallicRoughnessTexture":{"index":0,"extensions":{"KHR_texture_transform":
          {"offset":[0.25,0.5],"rotation":1.5707963,"scale":[2,3],"texCoord":1}}}},
      "emissiveTexture":{"index":0}}])"));
  ASSERT_EQ(scene.meshes[0].uvs1.size(), 3u);
  EXPECT_EQ(scene.meshes[0].uvs1[2], glm::vec2(9, 10));
  const wp::Texture& base = scene.textures.at(size_t(scene.materials[0].baseColorTexture));
  const wp::Texture& transformed = scene.textures.at(size_t(scene.materials[0].metallicRoughnessTexture));
  const wp::Texture& emissive = scene.textures.at(size_t(scene.materials[0].emissiveTexture));
  EXPECT_EQ(base.texCoord, 1);
  EXPECT_EQ(base.uvTransform, glm::mat3(1.0f));
  EXPECT_EQ(emissive.texCoord, 0);
  EXPECT_EQ(transformed.texCoord, 1);
  // A quarter turn: (u, v) = (1, 0) scales to (2, 0), turns to (0, 2), moves to (0.25, 2.5).
  const glm::vec3 moved = transformed.uvTransform * glm::vec3(1, 0, 1);
  EXPECT_NEAR(moved.x, 0.25f, 1e-6f);
  EXPECT_NEAR(moved.y, 2.5f, 1e-6f);
  // The layered extensions' textures are textureInfos too: their texCoord and transform hold.
  const Scene layered = load(file.json(rest + R"("extensionsUsed":["KHR_materials_clearcoat","KHR_texture_transform"],
    "materials":[{"extensions":{"KHR_materials_clearcoat":{"clearcoatFactor":1,
      "clearcoatTexture":{"index":0,"texCoord":1},
      "clearcoatRoughnessTexture":{"index":0,"extensions":{"KHR_texture_transform":{"offset":[0.5,0]}}}}}}])"));
  const wp::Material& coat = layered.materials[0];
  EXPECT_EQ(layered.textures.at(size_t(coat.clearcoatTexture)).texCoord, 1);
  const wp::Texture& coatRoughness = layered.textures.at(size_t(coat.clearcoatRoughnessTexture));
  EXPECT_EQ(coatRoughness.texCoord, 0);
  EXPECT_NEAR((coatRoughness.uvTransform * glm::vec3(0, 0, 1)).x, 0.5f, 1e-6f);
  std::string printed;
  load(file.json(rest + R"("materials":[{"emissiveTexture":{"index":0,"texCoord":2}}])"), &printed);
  EXPECT_NE(printed.find("TEXCOORD_2 or later"), std::string::npos) << printed;
  printed.clear();
  load(file.json(rest + R"("extensionsUsed":["KHR_materials_sheen"],"materials":[{"extensions":{
      "KHR_materials_sheen":{"sheenColorFactor":[1,1,1],"sheenColorTexture":{"index":0,"texCoord":3}}}}])"),
       &printed);
  EXPECT_NE(printed.find("TEXCOORD_2 or later"), std::string::npos) << printed;
  EXPECT_NE(errorOfJson(file.json(rest + R"("materials":[{"emissiveTexture":{"index":0,
      "extensions":{"KHR_texture_transform":{"scale":[1]}}}}])"))
                .find("KHR_texture_transform.scale must be 2 finite numbers"),
            std::string::npos);
}

TEST_F(SceneTest, RejectsMissingAndUndecodableImages) {
  GltfFile file = triangleFile();
  file.accessor(file.view(bytesOf(std::vector<glm::vec2>{{0, 0}, {1, 0}, {0, 1}})), 0, kFloat, 3, "VEC2");
  const std::string missing = errorOfJson(file.json(kTexturedMaterial + R"("images":[{"uri":"nowhere.png"}])"));
  EXPECT_NE(missing.find("nowhere.png"), std::string::npos) << missing;
  const std::string garbage =
      errorOfJson(file.json(kTexturedMaterial + R"("images":[{"uri":"data:image/png;base64,)" +
                            base64("this is not an image") + R"("}])"));
  EXPECT_NE(garbage.find("texture 0: image 0 (a data: URI) cannot be decoded (not a PNG, JPEG or WebP image)"),
            std::string::npos)
      << garbage;
  const std::string index = errorOfJson(file.json(R"(
    "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":3}}}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  EXPECT_NE(index.find("material 0: texture 3 does not exist"), std::string::npos) << index;
}

TEST_F(SceneTest, AppendsTheDefaultMaterialOnceForPrimitivesWithout) {
  GltfFile file = triangleFile();
  const Scene scene = load(file.json(R"(
    "materials":[{"name":"red","pbrMetallicRoughness":{"baseColorFactor":[1,0,0,1]}}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}},{"attributes":{"POSITION":0},"material":0}]},
              {"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0},{"mesh":1}],"scenes":[{"nodes":[0,1]}])"));
  ASSERT_EQ(scene.materials.size(), 2u);
  expectNear(scene.materials[1].baseColor, {1, 1, 1});
  EXPECT_FALSE(scene.materials[1].isEmissive());
  EXPECT_EQ(scene.meshes[0].materials, (std::vector<uint32_t>{1, 0}));
  EXPECT_EQ(scene.meshes[1].materials, (std::vector<uint32_t>{1}));
}

TEST_F(SceneTest, LightsAScenesWithoutEmittersWithAWhiteSky) {
  GltfFile file;
  file.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
  file.indices({0, 1, 2});
  file.indices({3, 4, 5});  // on a line: an emissive triangle without area emits nothing
  std::string printed;
  const Scene scene = load(file.json(R"(
    "materials":[{"emissiveFactor":[1,1,1]}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]},
              {"primitives":[{"attributes":{"POSITION":0},"indices":2,"material":0}]}],
    "nodes":[{"mesh":0},{"mesh":1}],"scenes":[{"nodes":[0,1]}])"),
                           &printed);
  ASSERT_EQ(scene.sky.width * scene.sky.height, 1u);
  EXPECT_EQ(scene.sky.radiance[0], glm::vec4(1, 1, 1, 0));
  EXPECT_NE(printed.find("wavepath: note: " + (dir_ / "scene.gltf").string() +
                         " has no lamps or emitters: lighting it with a constant white sky (--sky-color R,G,B"),
            std::string::npos)
      << printed;
}

// The default-lighting rule (default_lighting.h): emitters no brighter than the white sky
// glow, and the sky stays, with a note that says how to turn it off; an emitter brighter than
// it (here a sphere, through KHR_materials_emissive_strength) or a lamp lights the scene, and
// the sky goes, with a note that says how to add one.
TEST_F(SceneTest, OnlyLampsOrEmittersBrighterThanTheSkyTurnTheWhiteSkyOff) {
  GltfFile file = triangleFile();
  const auto loadWith = [&](const std::string& strength, const std::string& lamps, std::string* printed) {
    return load(file.json(R"("extensionsUsed":["KHR_materials_emissive_strength","KHR_lights_punctual"],
      "extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","intensity":100}]}},
      "materials":[{"emissiveFactor":[1,1,1],
                    "extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":)" + strength + R"(}}}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
      "nodes":[{"mesh":0},{"extras":{"wavepath":{"shape":"sphere","radius":1,"material":0}}})" + lamps + R"(],
      "scenes":[{"nodes":[0,1)" + (lamps.empty() ? "" : ",2") + R"(]}])"),
                printed);
  };
  std::string printed;
  Scene glowing = loadWith("1", "", &printed);
  EXPECT_EQ(glowing.sky.width, 1u);
  EXPECT_NE(printed.find("its emitters are no brighter than a white sky (they glow rather than light): lighting it "
                         "with a constant white sky too; --sky none turns it off"),
            std::string::npos)
      << printed;
  Scene bright = loadWith("1.5", "", &printed);
  EXPECT_EQ(bright.sky.width, 0u);
  EXPECT_NE(printed.find("is lit by its emitters brighter than a white sky, so it gets no sky; --sky-color R,G,B or "
                         "--sky FILE adds one"),
            std::string::npos)
      << printed;
  Scene lamp = loadWith("1", R"(,{"extensions":{"KHR_lights_punctual":{"light":0}}})", &printed);
  EXPECT_EQ(lamp.sky.width, 0u);
  EXPECT_NE(printed.find("is lit by its 1 lamp, so it gets no sky"), std::string::npos) << printed;
  wp::LoadOptions ownSky;
  ownSky.defaultSky = false;
  Scene glowingWithoutRule = load(file.json(R"("materials":[{"emissiveFactor":[1,1,1]}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"nodes":[{"mesh":0}],
    "scenes":[{"nodes":[0]}])"), &printed, ownSky);
  EXPECT_EQ(glowingWithoutRule.sky.width, 0u);
  EXPECT_EQ(printed, "");
}

// --- lamps (KHR_lights_punctual) ---

// Each kind, placed by its node (at the node origin, pointing down its -z), in W/sr or W/m^2:
// colour times candela or lux / 683; a light under an animated node is posed with it; a
// light's range is ignored with one note; KHR_lights_punctual in extensionsRequired loads.
TEST_F(SceneTest, ReadsPunctualLightsPlacedByTheirNodes) {
  GltfFile file = triangleFile();
  std::string printed;
  const Scene scene = load(file.json(R"("extensionsUsed":["KHR_lights_punctual"],
    "extensionsRequired":["KHR_lights_punctual"],
    "extensions":{"KHR_lights_punctual":{"lights":[
      {"name":"bulb","type":"point","color":[1,0.5,0.25],"intensity":683,"range":5},
      {"type":"spot","intensity":1366,"spot":{"innerConeAngle":0.2,"outerConeAngle":0.5}},
      {"type":"directional","intensity":6830}]}},
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0},{"translation":[1,2,3],"extensions":{"KHR_lights_punctual":{"light":0}}},
             {"rotation":[0.7071068,0,0,0.7071068],"translation":[0,5,0],"scale":[2,2,2],
              "extensions":{"KHR_lights_punctual":{"light":1}}},
             {"rotation":[0,0.7071068,0,0.7071068],"extensions":{"KHR_lights_punctual":{"light":2}}}],
    "scenes":[{"nodes":[0,1,2,3]}])"),
                           &printed);
  ASSERT_EQ(scene.lights.size(), 3u);
  const wp::PunctualLight& bulb = scene.lights[0];
  EXPECT_EQ(bulb.kind, wp::PunctualLight::Kind::Point);
  EXPECT_EQ(bulb.name, "bulb");
  expectNear(bulb.intensity, {1.0f, 0.5f, 0.25f});
  expectNear(bulb.position(), {1, 2, 3});
  const wp::PunctualLight& spot = scene.lights[1];
  EXPECT_EQ(spot.kind, wp::PunctualLight::Kind::Spot);
  expectNear(spot.intensity, {2, 2, 2});
  EXPECT_FLOAT_EQ(spot.innerConeAngle, 0.2f);
  EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.5f);
  expectNear(spot.position(), {0, 5, 0});
  expectNear(spot.direction(), {0, 1, 0});  // -z turned 90 degrees about +x; the scale does not count
  const wp::PunctualLight& sun = scene.lights[2];
  EXPECT_EQ(sun.kind, wp::PunctualLight::Kind::Directional);
  expectNear(sun.intensity, {10, 10, 10});
  expectNear(sun.direction(), {-1, 0, 0});  // -z turned 90 degrees about +y
  EXPECT_NE(printed.find("range is ignored"), std::string::npos) << printed;
}

TEST_F(SceneTest, RejectsMalformedPunctualLights) {
  GltfFile file = triangleFile();
  auto errorOf = [&](const std::string& light, const std::string& nodeLight = "0") {
    return errorOfJson(file.json(R"("extensionsUsed":["KHR_lights_punctual"],
      "extensions":{"KHR_lights_punctual":{"lights":[)" + light + R"(]}},
      "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
      "nodes":[{"mesh":0},{"extensions":{"KHR_lights_punctual":{"light":)" + nodeLight + R"(}}}],
      "scenes":[{"nodes":[0,1]}])"));
  };
  EXPECT_NE(errorOf(R"({"type":"area"})").find("light 0: type 'area' is not point, spot or directional; fix the light"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type":"point","intensity":-1})").find("intensity must be a finite number >= 0"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type":"point","color":[1,-1,1]})").find("color must be 3 finite numbers >= 0"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type":"spot","spot":{"innerConeAngle":0.6,"outerConeAngle":0.5}})")
                .find("spot cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= pi/2"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type":"point"})", "3").find("node 1: KHR_lights_punctual.light 3 does not exist"),
            std::string::npos);
}

// --- cameras ---

// Three cameras: an orthographic one in the file's first place, a perspective one under a
// parent that moves it by (0,0,-1) and turns it half a turn about y (to look down +z), and a
// third; the scene's walk reaches the perspective one first.
const std::string kThreeCameras = R"(
    "cameras":[{"name":"top","type":"orthographic","orthographic":{"xmag":3,"ymag":2,"znear":0.1,"zfar":10}},
               {"name":"main","type":"perspective","perspective":{"yfov":0.5,"aspectRatio":1.5,"znear":0.01}},
               {"type":"perspective","perspective":{"yfov":1.0,"znear":0.01}}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0},{"name":"high","camera":0,"translation":[0,9,0],"rotation":[-0.7071068,0,0,0.7071068]},
             {"translation":[0,0,-1],"rotation":[0,1,0,0],"children":[3]},
             {"camera":1,"translation":[1,2,3]},
             {"name":"third","camera":2}],
    "scenes":[{"nodes":[0,2,1,4]},{"nodes":[0]}])";

TEST_F(SceneTest, TakesTheFirstCameraOfTheWalk) {
  GltfFile file = triangleFile();
  const Scene scene = load(file.json(kThreeCameras));
  ASSERT_TRUE(scene.hasCamera);
  expectNear(scene.camera.position, {-1, 2, -4});
  expectNear(scene.camera.forward, {0, 0, 1});
  expectNear(scene.camera.up, {0, 1, 0});
  EXPECT_FLOAT_EQ(scene.camera.yfov, 0.5f);
  EXPECT_FLOAT_EQ(scene.camera.aspectRatio, 1.5f);
  EXPECT_FALSE(scene.camera.orthographic);
}

// --camera picks by index, by the camera's name or by its node's name; an orthographic camera
// keeps ymag as its half height and xmag / ymag as its aspect ratio.
TEST_F(SceneTest, PicksTheCameraTheFlagNames) {
  GltfFile file = triangleFile();
  for (const char* selection : {"0", "top", "high"}) {
    wp::LoadOptions options;
    options.camera = selection;
    const Scene scene = load(file.json(kThreeCameras), nullptr, options);
    SCOPED_TRACE(selection);
    ASSERT_TRUE(scene.hasCamera);
    EXPECT_TRUE(scene.camera.orthographic);
    EXPECT_FLOAT_EQ(scene.camera.orthographicHalfHeight, 2.0f);
    EXPECT_FLOAT_EQ(scene.camera.aspectRatio, 1.5f);
    expectNear(scene.camera.position, {0, 9, 0});
    expectNear(scene.camera.forward, {0, -1, 0});
  }
  wp::LoadOptions third;
  third.camera = "third";
  EXPECT_FLOAT_EQ(load(file.json(kThreeCameras), nullptr, third).camera.yfov, 1.0f);
  wp::LoadOptions missing;
  missing.camera = "7";
  EXPECT_NE(errorOfJson(file.json(kThreeCameras), missing)
                .find("--camera 7 names no camera of scene 0 (its cameras: camera 0 'top', camera 1 'main', camera 2); "
                      "give a camera's index or name"),
            std::string::npos);
}

// --scene picks a scene by index; one without anything to render, or past the last, is one
// error line.
TEST_F(SceneTest, PicksTheSceneTheFlagNames) {
  GltfFile file = triangleFile();
  wp::LoadOptions second;
  second.scene = 1;
  const Scene scene = load(file.json(kThreeCameras), nullptr, second);
  EXPECT_EQ(scene.instances.size(), 1u);
  EXPECT_FALSE(scene.hasCamera);  // scene 1 places no camera
  wp::LoadOptions third;
  third.scene = 2;
  EXPECT_NE(errorOfJson(file.json(kThreeCameras), third)
                .find("--scene 2: scene 2 does not exist (the file has 2 scenes); scenes count from 0"),
            std::string::npos);
  EXPECT_NE(errorOfJson(file.json(R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]},{"nodes":[]}])"), second).find("nothing to render: scene 1 has no triangles, spheres or planes; add a triangle mesh or a wavepath "
            "shape, or pick another scene with --scene N"),
            std::string::npos);
}

TEST_F(SceneTest, OrthogonalisesTheUpVectorAgainstAShearedForward) {
  GltfFile file = triangleFile();
  // A shear that tilts the node's -z towards +y leaves +y not orthogonal to the view.
  const Scene scene = load(file.json(R"(
    "cameras":[{"type":"perspective","perspective":{"yfov":0.8,"znear":0.01}}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0},{"camera":0,"matrix":[1,0,0,0, 0,1,0,0, 0,-1,1,0, 0,0,5,1]}],
    "scenes":[{"nodes":[0,1]}])"));
  ASSERT_TRUE(scene.hasCamera);
  EXPECT_FLOAT_EQ(scene.camera.aspectRatio, 0.0f);
  expectNear(scene.camera.position, {0, 0, 5});
  expectNear(scene.camera.forward, glm::normalize(glm::vec3(0, 1, -1)));
  EXPECT_NEAR(glm::dot(scene.camera.up, scene.camera.forward), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(scene.camera.up), 1.0f, 1e-6f);
  EXPECT_GT(scene.camera.up.y, 0.0f);
}

TEST_F(SceneTest, FramesTheSceneWhenThereIsNoCamera) {
  GltfFile file;
  file.positions({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}});
  std::string printed;
  const Scene scene = load(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0,"translation":[10,0,0]},
             {"translation":[10,0,-4],"extras":{"wavepath":{"shape":"sphere","radius":1}}},
             {"extras":{"wavepath":{"shape":"plane"}}}],
    "scenes":[{"nodes":[0,1,2]}])"),
                           &printed);
  EXPECT_FALSE(scene.hasCamera);
  // Bounds (9,-1,-5)..(11,1,0), the plane ignored: centre (10,0,-2.5), radius sqrt(33)/2.
  const glm::vec3 centre(10, 0, -2.5f);
  const float radius = std::sqrt(33.0f) / 2;
  expectNear(scene.camera.forward, {0, 0, -1});
  expectNear(scene.camera.up, {0, 1, 0});
  EXPECT_FLOAT_EQ(scene.camera.yfov, std::numbers::pi_v<float> / 4);
  EXPECT_FLOAT_EQ(scene.camera.aspectRatio, 0.0f);
  EXPECT_NEAR(scene.camera.position.x, centre.x, 1e-5f);
  EXPECT_NEAR(scene.camera.position.y, centre.y, 1e-5f);
  // The bounding sphere fits in the field of view, with a margin of at most a quarter.
  const float distance = scene.camera.position.z - centre.z;
  const float fits = radius / std::sin(std::numbers::pi_v<float> / 8);
  EXPECT_GE(distance, fits);
  EXPECT_LE(distance, 1.25f * fits);
}

// --- analytic shapes in extras ---

TEST_F(SceneTest, ReadsSpheresAndPlanesFromExtras) {
  GltfFile file = triangleFile();
  const Scene scene = load(file.json(R"(
    "materials":[{"name":"a"},{"name":"b"}],
    "nodes":[{"translation":[1,2,3],"scale":[2,2,2],
              "extras":{"wavepath":{"shape":"sphere","radius":0.5,"material":1}}},
             {"translation":[0,0,5],"rotation":[0.70710678,0,0,0.70710678],
              "extras":{"wavepath":{"shape":"plane","material":0}}},
             {"translation":[0,-1,0],"scale":[1,4,1],"extras":{"wavepath":{"shape":"plane"}}}],
    "scenes":[{"nodes":[0,1,2]}])"));
  ASSERT_EQ(scene.spheres.size(), 1u);
  const wp::Sphere& sphere = scene.spheres[0];
  EXPECT_EQ(sphere.material, 1u);
  // Radius 0.5 in node units, node scale 2: a unit sphere centred at (1,2,3).
  expectNear(glm::vec3(sphere.objectToWorld * glm::vec4(0, 0, 0, 1)), {1, 2, 3});
  expectNear(glm::vec3(sphere.objectToWorld * glm::vec4(1, 0, 0, 1)), {2, 2, 3});

  ASSERT_EQ(scene.planes.size(), 2u);
  // A quarter turn about x takes the node's +y to +z.
  expectNear(scene.planes[0].normal, {0, 0, 1});
  EXPECT_NEAR(scene.planes[0].distance, 5.0f, 1e-5f);
  EXPECT_EQ(scene.planes[0].material, 0u);
  // A scaled node keeps a unit normal; the plane without a material gets the default one.
  expectNear(scene.planes[1].normal, {0, 1, 0});
  EXPECT_NEAR(scene.planes[1].distance, -1.0f, 1e-5f);
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.planes[1].material, 2u);
  EXPECT_TRUE(scene.meshes.empty());
}

// --- errors: one line naming the file, what is wrong and what to do ---

TEST_F(SceneTest, RejectsAMissingFile) {
  EXPECT_NE(errorOf(dir_ / "nothing.gltf").find("no such file"), std::string::npos);
}

TEST_F(SceneTest, RejectsADirectory) {
  fs::create_directories(dir_ / "folder.gltf");
  EXPECT_NE(errorOf(dir_ / "folder.gltf").find("is a directory"), std::string::npos);
}

TEST_F(SceneTest, RejectsMalformedJson) {
  const std::string message = errorOfJson(R"({"asset":{"version":"2.0"},"nodes":[{"mesh":0},)");
  EXPECT_NE(message.find("is not a valid glTF 2.0 file"), std::string::npos) << message;
  EXPECT_NE(message.find("parse error"), std::string::npos) << message;
}

TEST_F(SceneTest, RejectsATruncatedGlb) {
  GltfFile file = triangleFile();
  const std::string glb = file.glb(kOneTriangle);
  for (size_t length : {size_t(3), size_t(16), size_t(40), glb.size() - 4}) {
    const std::string message = errorOf(write("cut.glb", glb.substr(0, length)));
    EXPECT_TRUE(message.find("not a valid glTF") != std::string::npos ||
                message.find("not a binary glTF") != std::string::npos)
        << length << ": " << message;
  }
}

TEST_F(SceneTest, RejectsAMissingBufferFile) {
  GltfFile file = triangleFile();
  const std::string message = errorOfJson(file.json(kOneTriangle, "missing.bin"));
  EXPECT_NE(message.find("missing.bin"), std::string::npos) << message;
  EXPECT_NE(message.find("not found"), std::string::npos) << message;
}

TEST_F(SceneTest, RejectsAnIndexOutOfRange) {
  GltfFile file = triangleFile();
  file.indices({0, 1, 7}, kU16);
  const std::string message = errorOfJson(file.json(R"(
    "meshes":[{"name":"Cube","primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  EXPECT_NE(message.find("mesh 0 'Cube' primitive 0: index 7 is out of range (the POSITION accessor has 3 vertices)"),
            std::string::npos)
      << message;
}

TEST_F(SceneTest, RejectsAnAccessorOutsideItsBuffer) {
  GltfFile file;
  const int view = file.view(bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  file.accessor(view, 12, kFloat, 3, "VEC3");
  const std::string message = errorOfJson(file.json(kOneTriangle));
  EXPECT_NE(message.find("accessor 0: 3 elements from byte offset 12"), std::string::npos) << message;
  EXPECT_NE(message.find("do not fit"), std::string::npos) << message;
}

TEST_F(SceneTest, RejectsPositionsThatAreNotVec3) {
  GltfFile file;
  file.indices({0, 1, 2}, kU16);
  const std::string message = errorOfJson(file.json(kOneTriangle));
  EXPECT_NE(message.find("POSITION must be VEC3 of FLOAT or 8- or 16-bit integers, not UNSIGNED_SHORT SCALAR"),
            std::string::npos)
      << message;
}

TEST_F(SceneTest, RejectsNonFinitePositions) {
  GltfFile file;
  file.positions({{0, 0, 0}, {1, NAN, 0}, {0, 1, 0}});
  const std::string message = errorOfJson(file.json(kOneTriangle));
  EXPECT_NE(message.find("vertex 1 of the POSITION accessor 0 is not finite"), std::string::npos) << message;
  GltfFile infinite;
  infinite.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, INFINITY}});
  EXPECT_NE(errorOfJson(infinite.json(kOneTriangle)).find("is not finite"), std::string::npos);
}

TEST_F(SceneTest, RejectsAMissingMaterial) {
  GltfFile file = triangleFile();
  const std::string message = errorOfJson(file.json(R"(
    "materials":[{}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":3}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  EXPECT_NE(message.find("mesh 0 primitive 0: material 3 does not exist (the file has 1 material)"), std::string::npos)
      << message;
}

TEST_F(SceneTest, RejectsANodeCycle) {
  GltfFile file = triangleFile();
  const std::string message = errorOfJson(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"name":"a","mesh":0,"children":[1]},{"name":"b","children":[0]}],"scenes":[{"nodes":[0]}])"));
  EXPECT_NE(message.find("node 0 'a': it is its own ancestor, so the node hierarchy has a cycle"), std::string::npos)
      << message;
}

TEST_F(SceneTest, RejectsANodeWithTwoParents) {
  GltfFile file = triangleFile();
  const std::string message = errorOfJson(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"children":[2]},{"children":[2]},{"name":"wheel","mesh":0}],"scenes":[{"nodes":[0,1]}])"));
  EXPECT_NE(message.find("node 2 'wheel': it is a child of both node 0 and node 1, but a glTF node may have only one "
                         "parent"),
            std::string::npos)
      << message;
}

TEST_F(SceneTest, RejectsAMissingChildNode) {
  GltfFile file = triangleFile();
  const std::string message = errorOfJson(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "nodes":[{"mesh":0,"children":[5]}],"scenes":[{"nodes":[0]}])"));
  EXPECT_NE(message.find("node 0: child node 5 does not exist (the file has 1 node)"), std::string::npos) << message;
}

TEST_F(SceneTest, RejectsAnUnsupportedRequiredExtension) {
  GltfFile file = triangleFile();
  const std::string message = errorOfJson(file.json(R"(
    "extensionsUsed":["KHR_materials_pbrSpecularGlossiness","KHR_materials_emissive_strength"],
    "extensionsRequired":["KHR_materials_pbrSpecularGlossiness","KHR_materials_emissive_strength"],)" +
                                                    kOneTriangle));
  EXPECT_NE(message.find("requires extension KHR_materials_pbrSpecularGlossiness, which wavepath does not support"),
            std::string::npos)
      << message;
}

TEST_F(SceneTest, WarnsOnceAboutUnsupportedUsedExtensions) {
  GltfFile file = triangleFile();
  std::string printed;
  load(file.json(R"(
    "extensionsUsed":["EXT_lights_image_based","KHR_materials_emissive_strength","KHR_materials_anisotropy"],)" +
                 kOneTriangle),
       &printed);
  EXPECT_NE(printed.find("extensions EXT_lights_image_based, KHR_materials_anisotropy ignored, the image may differ "
                         "from other viewers"),
            std::string::npos)
      << printed;
}

TEST_F(SceneTest, RejectsASceneWithNothingToRender) {
  GltfFile file = triangleFile();
  const std::string message = errorOfJson(file.json(R"(
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":1}]}],
    "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])"));
  EXPECT_NE(message.find("nothing to render"), std::string::npos) << message;
  EXPECT_NE(errorOfJson(R"({"asset":{"version":"2.0"}})").find("nothing to render"), std::string::npos);
}

TEST_F(SceneTest, RejectsBadExtras) {
  GltfFile file = triangleFile();
  const auto errorOfShape = [&](const std::string& shape) {
    return errorOfJson(file.json(R"("materials":[{}],"nodes":[{"name":"s","extras":{"wavepath":)" + shape +
                                 R"(}}],"scenes":[{"nodes":[0]}])"));
  };
  EXPECT_NE(errorOfShape(R"({"shape":"cube"})").find("node 0 's': unknown extras.wavepath.shape 'cube'"),
            std::string::npos);
  EXPECT_NE(errorOfShape(R"({"radius":1})").find("extras.wavepath needs a \"shape\""), std::string::npos);
  for (const std::string radius : {"0", "-1", "\"big\"", "[1]"}) {
    EXPECT_NE(errorOfShape(R"({"shape":"sphere","radius":)" + radius + "}")
                  .find("a sphere's extras.wavepath.radius must be a number > 0"),
              std::string::npos)
        << radius;
  }
  EXPECT_NE(errorOfShape(R"({"shape":"sphere"})").find("radius must be a number > 0"), std::string::npos);
  for (const std::string material : {"1", "-1", "0.5", "\"a\""}) {
    EXPECT_NE(errorOfShape(R"({"shape":"plane","material":)" + material + "}")
                  .find("extras.wavepath.material must be an index of the materials array (the file has 1 "
                        "material)"),
              std::string::npos)
        << material;
  }
}

TEST_F(SceneTest, RejectsAbsurdlyDeepJsonWithoutCrashing) {
  const std::string deep = R"({"asset":{"version":"2.0"},"extras":)" + std::string(100000, '[') +
                           std::string(100000, ']') + "}";
  EXPECT_NE(errorOfJson(deep).find("nests deeper"), std::string::npos);
}

// --- the shipped Cornell box ---

TEST(CornellBox, MatchesThePublishedScene) {
  const char* source = std::getenv("WAVEPATH_SOURCE_DIR");
  ASSERT_NE(source, nullptr) << "WAVEPATH_SOURCE_DIR is not set";
  ::testing::internal::CaptureStderr();
  const Scene scene = loadScene(fs::path(source) / "assets" / "cornell-box.gltf");
  const std::string printed = ::testing::internal::GetCapturedStderr();
  // The only line it prints is the lighting rule's (default_lighting.h): its lamp is brighter
  // than a white sky, so it gets none.
  EXPECT_NE(printed.find("is lit by its emitters brighter than a white sky, so it gets no sky"), std::string::npos)
      << printed;
  EXPECT_EQ(std::count(printed.begin(), printed.end(), '\n'), 1) << printed;

  // Floor, ceiling, three walls, two blocks of five quads and the light: 16 quads.
  EXPECT_EQ(scene.meshes.size(), 8u);
  EXPECT_EQ(scene.instances.size(), 8u);
  size_t triangles = 0;
  size_t emissive = 0;
  glm::vec3 lo(1e9f);
  glm::vec3 hi(-1e9f);
  for (const wp::MeshInstance& instance : scene.instances) {
    const wp::Mesh& mesh = scene.meshes[instance.mesh];
    triangles += mesh.triangleCount();
    for (uint32_t m : mesh.materials) emissive += scene.materials[m].isEmissive() ? 1 : 0;
    for (const glm::vec3& p : mesh.positions) {
      const glm::vec3 w(instance.objectToWorld * glm::vec4(p, 1.0f));
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
  }
  EXPECT_EQ(triangles, 32u);
  EXPECT_EQ(emissive, 2u);
  expectNear(lo, {0, 0, 0});
  expectNear(hi, {0.556f, 0.5488f, 0.5592f});

  ASSERT_EQ(scene.materials.size(), 4u);
  const wp::Material& light = scene.materials[3];
  expectNear(light.emission, {18.387f, 10.9873f, 2.75357f}, 1e-4f);
  expectNear(light.baseColor, {0, 0, 0});
  EXPECT_FALSE(light.doubleSided);
  expectNear(scene.materials[1].baseColor, {0.570068f, 0.0430135f, 0.0443706f});
  EXPECT_EQ(scene.sky.width, 0u);

  ASSERT_TRUE(scene.hasCamera);
  expectNear(scene.camera.position, {0.278f, 0.273f, -0.8f});
  expectNear(scene.camera.forward, {0, 0, 1});
  expectNear(scene.camera.up, {0, 1, 0});
  EXPECT_NEAR(scene.camera.yfov, 39.3077f * std::numbers::pi_v<float> / 180.0f, 1e-6f);
  EXPECT_FLOAT_EQ(scene.camera.aspectRatio, 1.0f);

  // The light faces down (its triangles wind clockwise seen from above).
  const wp::Mesh& lightMesh = scene.meshes[scene.instances[7].mesh];
  const glm::vec3 a = lightMesh.positions[lightMesh.indices[0]];
  const glm::vec3 normal =
      glm::cross(lightMesh.positions[lightMesh.indices[1]] - a, lightMesh.positions[lightMesh.indices[2]] - a);
  EXPECT_LT(normal.y, 0.0f);
  EXPECT_NEAR(a.y, 0.5483f, 1e-6f);
}

}  // namespace
