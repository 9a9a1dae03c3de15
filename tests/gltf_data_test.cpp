// Tests of how the loader reads glTF data: sparse accessors, KHR_mesh_quantization's integer
// attributes, meshes compressed with Draco or meshopt (decoded into the same vertices and
// triangles as their original), with the errors of damaged data; and images: WebP, the
// fallbacks of KTX2 textures, and errors that name the extension or the image file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <stb_image_write.h>
#include <webp/encode.h>

#include "core/error.h"
#include "samples/gltf_builder.h"
#include "samples/gltf_samples.h"
#include "scene/gltf_loader.h"

namespace wp {
namespace {

namespace fs = std::filesystem;
using samples::bytesOf;
using samples::GltfBuilder;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("wavepath_gltf_data_test_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// One triangle primitive on the given attributes, in node 0 of scene 0.
void addTriangleMesh(GltfBuilder& file, const nlohmann::json& attributes) {
  file.json["meshes"] = {{{"primitives", {{{"attributes", attributes}}}}}};
  file.json["nodes"] = {{{"mesh", 0}}};
  file.json["scenes"] = {{{"nodes", {0}}}};
}

std::string errorOf(const fs::path& file) {
  try {
    loadScene(file);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

TEST(GltfData, SparseAccessorReplacesTheListedElements) {
  GltfBuilder file;
  const int position = file.addFloats(kTriangle, "VEC3", 3);
  file.json["accessors"][0]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", file.addView(bytesOf(std::vector<uint8_t>{2, 0, 0, 0}))}, {"componentType", 5121}}},
      {"values", {{"bufferView", file.addView(bytesOf(std::vector<float>{0, 3, 4}))}}}};
  addTriangleMesh(file, {{"POSITION", position}});
  const Scene scene = loadScene(file.write(scratch("sparse"), "sparse"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const std::vector<glm::vec3>& p = scene.meshes[0].positions;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(p[2], glm::vec3(0, 3, 4));
}

TEST(GltfData, SparseAccessorWithoutABufferViewStartsFromZeros) {
  GltfBuilder file;
  const int position = file.addAccessor(-1, samples::kFloat, 3, "VEC3");
  file.json["accessors"][0]["sparse"] = {
      {"count", 2},
      {"indices", {{"bufferView", file.addView(bytesOf(std::vector<uint16_t>{1, 2}))}, {"componentType", 5123}}},
      {"values", {{"bufferView", file.addView(bytesOf(std::vector<float>{1, 0, 0, 0, 1, 0}))}}}};
  file.json["accessors"][0]["min"] = {0, 0, 0};
  file.json["accessors"][0]["max"] = {1, 1, 0};
  addTriangleMesh(file, {{"POSITION", position}});
  const Scene scene = loadScene(file.write(scratch("sparse-zeros"), "sparse"));
  const std::vector<glm::vec3>& p = scene.meshes.at(0).positions;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0], glm::vec3(0, 0, 0));
  EXPECT_EQ(p[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(p[2], glm::vec3(0, 1, 0));
}

TEST(GltfData, RejectsASparseIndexOutOfRange) {
  GltfBuilder file;
  const int position = file.addFloats(kTriangle, "VEC3", 3);
  file.json["accessors"][0]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", file.addView(bytesOf(std::vector<uint32_t>{7}))}, {"componentType", 5125}}},
      {"values", {{"bufferView", file.addView(bytesOf(std::vector<float>{0, 3, 4}))}}}};
  addTriangleMesh(file, {{"POSITION", position}});
  const std::string message = errorOf(file.write(scratch("sparse-range"), "sparse"));
  EXPECT_NE(message.find("accessor 0: sparse index 7 is out of range (the accessor has 3 elements)"),
            std::string::npos)
      << message;
}

// KHR_mesh_quantization: positions as normalized SHORT, normals as normalized BYTE, texture
// coordinates as plain UNSIGNED_BYTE, each decoded as glTF 2.0 section 3.11 says.
TEST(GltfData, ReadsQuantizedAttributes) {
  GltfBuilder file;
  // 4 components to a vertex: xyz and padding, as 4-byte aligned vertex strides ask.
  const std::vector<int16_t> positions = {0, 0, 0, 0, 0, 32767, 0, 0, -16384, -32768, 0, 0};
  const std::vector<int8_t> normals = {0, 0, 127, 0, 127, 0, 0, 0, 0, -128, 0, 0};
  const std::vector<uint8_t> uvs = {0, 0, 2, 0, 0, 3};
  const int position = file.addAccessor(file.addView(bytesOf(positions), 8), samples::kShort, 3, "VEC3", true);
  file.json["accessors"][0]["min"] = {-0.5, -1, 0};
  file.json["accessors"][0]["max"] = {1, 1, 0};
  const int normal = file.addAccessor(file.addView(bytesOf(normals), 4), samples::kByte, 3, "VEC3", true);
  const int uv = file.addAccessor(file.addView(bytesOf(uvs)), samples::kUnsignedByte, 3, "VEC2");
  addTriangleMesh(file, {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}});
  file.useExtension("KHR_mesh_quantization", true);
  const Scene scene = loadScene(file.write(scratch("quantized"), "quantized"));
  const Mesh& mesh = scene.meshes.at(0);
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.positions[1], glm::vec3(0, 1, 0));
  EXPECT_NEAR(mesh.positions[2].x, -16384.0f / 32767.0f, 1e-7f);
  EXPECT_EQ(mesh.positions[2].y, -1.0f);  // -32768 clamps to -1
  EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(mesh.normals[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(mesh.normals[2], glm::vec3(0, -1, 0));
  EXPECT_EQ(mesh.uvs[1], glm::vec2(2, 0));
  EXPECT_EQ(mesh.uvs[2], glm::vec2(0, 3));
}

// A vertex in world space with its normal and texture coordinates.
struct Vertex {
  glm::vec3 position, normal;
  glm::vec2 uv;
};

std::vector<Vertex> worldVertices(const Scene& scene) {
  const MeshInstance& instance = scene.instances.at(0);
  const Mesh& mesh = scene.meshes.at(instance.mesh);
  std::vector<Vertex> out;
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    out.push_back({glm::vec3(instance.objectToWorld * glm::vec4(mesh.positions[v], 1.0f)),
                   glm::normalize(glm::mat3(instance.objectToWorld) * mesh.normals.at(v)), mesh.uvs.at(v)});
  }
  return out;
}

// Each decoded vertex matches one of the original's within the codec's quantization, and
// the decoded triangles are the original's (in any order, each in any rotation).
void expectSameMesh(const Scene& original, const Scene& decoded, float positionStep, float normalStep, float uvStep) {
  const std::vector<Vertex> a = worldVertices(original);
  const std::vector<Vertex> b = worldVertices(decoded);
  std::vector<uint32_t> match(b.size());
  for (size_t v = 0; v < b.size(); ++v) {
    float best = 1e30f;
    for (size_t w = 0; w < a.size(); ++w) {
      const float d = glm::distance(a[w].position, b[v].position) / positionStep + glm::distance(a[w].uv, b[v].uv) / uvStep;
      if (d < best) best = d, match[v] = uint32_t(w);
    }
    const Vertex& m = a[match[v]];
    ASSERT_LT(glm::distance(m.position, b[v].position), positionStep) << "vertex " << v;
    ASSERT_LT(glm::distance(m.normal, b[v].normal), normalStep) << "vertex " << v;
    ASSERT_LT(glm::distance(m.uv, b[v].uv), uvStep) << "vertex " << v;
  }
  const auto triangles = [](const std::vector<uint32_t>& indices, const std::vector<uint32_t>* map) {
    std::vector<std::array<uint32_t, 3>> out;
    for (size_t t = 0; t < indices.size(); t += 3) {
      std::array<uint32_t, 3> tri{indices[t], indices[t + 1], indices[t + 2]};
      for (uint32_t& i : tri) i = map ? (*map)[i] : i;
      std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
      out.push_back(tri);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(triangles(decoded.meshes.at(0).indices, &match), triangles(original.meshes.at(0).indices, nullptr));
}

TEST(GltfData, DracoMeshDecodesToTheOriginal) {
  const fs::path dir = scratch("draco");
  const Scene plain = loadScene(samples::writeCompressedSphere(dir, samples::Compression::None));
  const Scene draco = loadScene(samples::writeCompressedSphere(dir, samples::Compression::Draco));
  // 14-bit positions over 2 m, 10-bit normals, 12-bit texture coordinates.
  expectSameMesh(plain, draco, 2.0f / 16383.0f * 1.8f, 4e-3f, 1.0f / 4095.0f);
}

TEST(GltfData, MeshoptMeshDecodesToTheOriginal) {
  const fs::path dir = scratch("meshopt");
  const Scene plain = loadScene(samples::writeCompressedSphere(dir, samples::Compression::None));
  const Scene meshopt = loadScene(samples::writeCompressedSphere(dir, samples::Compression::Meshopt));
  // 16-bit positions (the node's scale), 16-bit octahedral normals and texture coordinates.
  expectSameMesh(plain, meshopt, 2.0f / 65535.0f * 1.8f, 2e-4f, 1.0f / 65535.0f);
}

// Damaged compressed data is one error line naming the primitive or view, never a crash.
TEST(GltfData, RejectsDamagedCompressedData) {
  const fs::path dir = scratch("damaged");
  const fs::path draco = samples::writeCompressedSphere(dir, samples::Compression::Draco);
  const fs::path bin = dir / "compressed-draco.bin";
  std::vector<char> bytes(fs::file_size(bin));
  std::ifstream(bin, std::ios::binary).read(bytes.data(), std::streamsize(bytes.size()));
  // The checker PNG comes first; the Draco data follows at its 4-byte aligned end.
  const nlohmann::json json = nlohmann::json::parse(std::ifstream(draco));
  const size_t dracoStart = json["bufferViews"][1]["byteOffset"];
  std::fill(bytes.begin() + std::ptrdiff_t(dracoStart) + 8, bytes.end(), char(0x5a));
  std::ofstream(bin, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  std::string message = errorOf(draco);
  EXPECT_NE(message.find("mesh 0 'sphere' primitive 0: KHR_draco_mesh_compression data in buffer view 1 does not decode"),
            std::string::npos)
      << message;

  const fs::path meshopt = samples::writeCompressedSphere(dir, samples::Compression::Meshopt);
  nlohmann::json changed = nlohmann::json::parse(std::ifstream(meshopt));
  // View 2 holds the positions (view 1 their compressed bytes): 8 bytes each.
  changed["bufferViews"][2]["extensions"]["EXT_meshopt_compression"]["count"] = 5;
  std::ofstream(meshopt) << changed.dump();
  message = errorOf(meshopt);
  EXPECT_NE(message.find("buffer view 2: EXT_meshopt_compression decodes to 40 bytes (count times byteStride) but the "
                         "view has"),
            std::string::npos)
      << message;
}

// ---- images ----

std::vector<uint8_t> pngOf(glm::u8vec4 rgba) {
  std::vector<uint8_t> png;
  stbi_write_png_to_func(
      [](void* out, void* data, int size) {
        auto* bytes = static_cast<std::vector<uint8_t>*>(out);
        bytes->insert(bytes->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
      },
      &png, 1, 1, 4, &rgba, 4);
  return png;
}

std::vector<uint8_t> webpOf(glm::u8vec4 rgba) {
  uint8_t* encoded = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(&rgba.x, 1, 1, 4, &encoded);
  std::vector<uint8_t> webp(encoded, encoded + size);
  WebPFree(encoded);
  return webp;
}

// A triangle with texture coordinates whose material's base colour is texture 0.
GltfBuilder texturedTriangle(const nlohmann::json& texture, const nlohmann::json& images) {
  GltfBuilder file;
  const int position = file.addFloats(kTriangle, "VEC3", 3);
  const int uv = file.addFloats({0, 0, 1, 0, 0, 1}, "VEC2", 2);
  addTriangleMesh(file, {{"POSITION", position}, {"TEXCOORD_0", uv}});
  file.json["meshes"][0]["primitives"][0]["material"] = 0;
  file.json["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  file.json["textures"] = {texture};
  file.json["images"] = images;
  return file;
}

void writeBytes(const fs::path& file, const std::vector<uint8_t>& bytes) {
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// The first 12 bytes of every KTX2 file, then nothing a decoder could use.
const std::vector<uint8_t> kKtx2 = {0xab, 'K', 'T', 'X', ' ', '2', '0', 0xbb, '\r', '\n', 0x1a, '\n', 0, 0, 0, 0};

const glm::u8vec4 kRed(255, 0, 0, 255);
const glm::u8vec4 kGreen(0, 255, 0, 255);

TEST(GltfImages, WebpIsShownInsteadOfItsFallback) {
  const fs::path dir = scratch("webp");
  writeBytes(dir / "red.png", pngOf(kRed));
  writeBytes(dir / "green.webp", webpOf(kGreen));
  GltfBuilder file = texturedTriangle({{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}},
                                      {{{"uri", "red.png"}}, {{"uri", "green.webp"}, {"mimeType", "image/webp"}}});
  file.useExtension("EXT_texture_webp", false);
  const Scene scene = loadScene(file.write(dir, "webp"));
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.textures[0].rgba.at(0), 0xff00ff00u);  // r in the low byte
}

TEST(GltfImages, KtxTexturesShowTheirFallbackWithOneWarning) {
  const fs::path dir = scratch("ktx-fallback");
  writeBytes(dir / "red.png", pngOf(kRed));
  writeBytes(dir / "green.ktx2", kKtx2);
  GltfBuilder file = texturedTriangle({{"source", 0}, {"extensions", {{"KHR_texture_basisu", {{"source", 1}}}}}},
                                      {{{"uri", "red.png"}}, {{"uri", "green.ktx2"}, {"mimeType", "image/ktx2"}}});
  file.useExtension("KHR_texture_basisu", false);
  const fs::path path = file.write(dir, "ktx");
  ::testing::internal::CaptureStderr();
  const Scene scene = loadScene(path);
  const std::string printed = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.textures[0].rgba.at(0), 0xff0000ffu);
  EXPECT_NE(printed.find("1 of 1 textures have images for KHR_texture_basisu, which wavepath cannot decode: they "
                         "show their fallback images"),
            std::string::npos)
      << printed;
}

TEST(GltfImages, KtxWithoutAFallbackIsOneErrorNamingTheExtensionAndTheFile) {
  const fs::path dir = scratch("ktx-only");
  writeBytes(dir / "wood.ktx2", kKtx2);
  GltfBuilder file = texturedTriangle({{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}},
                                      {{{"uri", "wood.ktx2"}, {"mimeType", "image/ktx2"}}});
  file.useExtension("KHR_texture_basisu", true);
  const std::string message = errorOf(file.write(dir, "ktx"));
  EXPECT_NE(message.find("texture 0: its only image, image 0 ('wood.ktx2'), is for KHR_texture_basisu, which wavepath "
                         "cannot decode"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// An unsupported required extension is the error even when an image would not decode:
// the extensions are checked before any image is decoded.
TEST(GltfImages, ExtensionsAreCheckedBeforeImagesAreDecoded) {
  const fs::path dir = scratch("order");
  writeBytes(dir / "broken.webp", {'R', 'I', 'F', 'F', 0, 0, 0, 0, 'W', 'E', 'B', 'P', 1, 2, 3});
  GltfBuilder file = texturedTriangle({{"source", 0}}, {{{"uri", "broken.webp"}}});
  file.useExtension("KHR_materials_pbrSpecularGlossiness", true);
  const fs::path path = file.write(dir, "order");
  std::string message = errorOf(path);
  EXPECT_NE(message.find("requires extension KHR_materials_pbrSpecularGlossiness"), std::string::npos) << message;
  // Without it, the image's own error names its file.
  file.json.erase("extensionsRequired");
  file.json.erase("extensionsUsed");
  message = errorOf(file.write(dir, "order"));
  EXPECT_NE(message.find("material 0: texture 0: image 0 ('broken.webp') cannot be decoded (WebP: "), std::string::npos)
      << message;
}

}  // namespace
}  // namespace wp
