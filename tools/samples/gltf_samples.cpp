// Sample glTF files that each show one feature (in the style of Khronos' sample models),
// written by the project's own code for the tests and for assets/samples.
#include "samples/gltf_samples.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <glm/glm.hpp>
#include <meshoptimizer.h>

#include "samples/gltf_builder.h"

namespace wp::samples {

namespace {

using nlohmann::json;

struct SphereMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<uint32_t> indices;
};

// A latitude-longitude unit sphere with a seam of duplicated vertices, wound outwards.
SphereMesh uvSphere(int slices, int stacks) {
  SphereMesh mesh;
  for (int j = 0; j <= stacks; ++j) {
    const float theta = std::numbers::pi_v<float> * float(j) / float(stacks);
    for (int i = 0; i <= slices; ++i) {
      const float phi = 2.0f * std::numbers::pi_v<float> * float(i) / float(slices);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
      mesh.positions.push_back(n);
      mesh.normals.push_back(n);
      mesh.uvs.emplace_back(float(i) / float(slices), float(j) / float(stacks));
    }
  }
  const auto at = [slices](int i, int j) { return uint32_t(j * (slices + 1) + i); };
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  }
  return mesh;
}

std::vector<float> flatten(const std::vector<glm::vec3>& v) {
  std::vector<float> out;
  for (const glm::vec3& x : v) out.insert(out.end(), {x.x, x.y, x.z});
  return out;
}

std::vector<float> flatten(const std::vector<glm::vec2>& v) {
  std::vector<float> out;
  for (const glm::vec2& x : v) out.insert(out.end(), {x.x, x.y});
  return out;
}

// A camera at `eye` looking at `target` (up +y), a directional lamp shining along `light`
// (in lux, KHR_lights_punctual), and the scene of them and the `meshNodes`.
void addStage(GltfBuilder& file, glm::vec3 eye, glm::vec3 target, glm::vec3 light, float lux,
              const std::vector<int>& meshNodes) {
  const glm::vec3 forward = glm::normalize(target - eye);
  // Yaw about +y, then pitch about the camera's x: keeps the camera's up in the vertical plane.
  const float yaw = std::atan2(-forward.x, -forward.z);
  const float pitch = std::asin(forward.y);
  const glm::vec4 qYaw(0.0f, std::sin(yaw / 2), 0.0f, std::cos(yaw / 2));
  const glm::vec4 qPitch(std::sin(pitch / 2), 0.0f, 0.0f, std::cos(pitch / 2));
  const glm::vec4 q(qYaw.w * qPitch.x, qYaw.y * qPitch.w, -qYaw.y * qPitch.x, qYaw.w * qPitch.w);
  json& nodes = file.json["nodes"];
  std::vector<int> sceneNodes = meshNodes;
  sceneNodes.push_back(int(nodes.size()));
  nodes.push_back({{"name", "camera"}, {"camera", 0}, {"translation", {eye.x, eye.y, eye.z}},
                   {"rotation", {q.x, q.y, q.z, q.w}}});
  sceneNodes.push_back(int(nodes.size()));
  nodes.push_back({{"name", "sun"}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}},
                   {"rotation", rotationFromMinusZ(light)}});
  file.json["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.01}}}}};
  file.json["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "directional"}, {"intensity", lux}, {"name", "sun"}}};
  file.useExtension("KHR_lights_punctual", false);
  file.json["scene"] = 0;
  file.json["scenes"] = {{{"nodes", sceneNodes}}};
}

// An 8x8 checker of two colours as PNG bytes.
std::vector<uint8_t> checkerPng() {
  std::vector<uint8_t> rgb;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const bool dark = (x + y) % 2 == 1;
      rgb.insert(rgb.end(), dark ? std::initializer_list<uint8_t>{40, 60, 160} : std::initializer_list<uint8_t>{230, 200, 90});
    }
  }
  return encodePng(8, 8, 3, rgb);
}

// A Lambertian material with the checker as base colour texture, sampled NEAREST.
void addCheckerMaterial(GltfBuilder& file) {
  file.json["images"] = {{{"bufferView", file.addView(checkerPng())}, {"mimeType", "image/png"}}};
  file.json["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}}};
  file.json["textures"] = {{{"source", 0}, {"sampler", 0}}};
  file.json["materials"] = {{{"name", "checker"},
                             {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                             {"extras", {{"wavepath", {{"bsdf", "lambert"}}}}}}};
}

json dracoPrimitive(GltfBuilder& file, const SphereMesh& sphere) {
  draco::Mesh mesh;
  const size_t n = sphere.positions.size();
  mesh.set_num_points(uint32_t(n));
  const auto add = [&](draco::GeometryAttribute::Type type, int components, const float* values) {
    auto attribute = std::make_unique<draco::PointAttribute>();
    attribute->Init(type, int8_t(components), draco::DT_FLOAT32, false, n);
    for (size_t i = 0; i < n; ++i) {
      attribute->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)), values + i * size_t(components));
    }
    return mesh.AddAttribute(std::move(attribute));
  };
  const std::vector<float> positions = flatten(sphere.positions);
  const std::vector<float> normals = flatten(sphere.normals);
  const std::vector<float> uvs = flatten(sphere.uvs);
  const int position = add(draco::GeometryAttribute::POSITION, 3, positions.data());
  const int normal = add(draco::GeometryAttribute::NORMAL, 3, normals.data());
  const int uv = add(draco::GeometryAttribute::TEX_COORD, 2, uvs.data());
  for (size_t t = 0; t < sphere.indices.size(); t += 3) {
    mesh.AddFace({draco::PointIndex(sphere.indices[t]), draco::PointIndex(sphere.indices[t + 1]),
                  draco::PointIndex(sphere.indices[t + 2])});
  }
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
  draco::EncoderBuffer encoded;
  if (!encoder.EncodeMeshToBuffer(mesh, &encoded).ok()) throw std::runtime_error("Draco cannot encode the sphere");
  // The accessors state the decoded counts, which the encoder may change.
  draco::DecoderBuffer check;
  check.Init(encoded.data(), encoded.size());
  auto decoded = draco::Decoder().DecodeMeshFromBuffer(&check);
  if (!decoded.ok()) throw std::runtime_error("Draco cannot decode its own sphere");
  const size_t points = decoded.value()->num_points();
  const size_t corners = size_t(decoded.value()->num_faces()) * 3;
  const std::vector<uint8_t> bytes(encoded.data(), encoded.data() + encoded.size());
  const int view = file.addView(bytes);
  const int positionAccessor = file.addAccessor(-1, kFloat, points, "VEC3");
  file.json["accessors"][size_t(positionAccessor)]["min"] = {-1, -1, -1};
  file.json["accessors"][size_t(positionAccessor)]["max"] = {1, 1, 1};
  json primitive = {{"attributes",
                     {{"POSITION", positionAccessor},
                      {"NORMAL", file.addAccessor(-1, kFloat, points, "VEC3")},
                      {"TEXCOORD_0", file.addAccessor(-1, kFloat, points, "VEC2")}}},
                    {"indices", file.addAccessor(-1, kUnsignedShort, corners, "SCALAR")}};
  primitive["extensions"]["KHR_draco_mesh_compression"] = {
      {"bufferView", view}, {"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}}};
  file.useExtension("KHR_draco_mesh_compression", true);
  return primitive;
}

// Views on the fallback buffer (1) whose bytes come from meshopt data in buffer 0.
struct MeshoptStreams {
  GltfBuilder& file;
  size_t fallbackBytes = 0;

  int add(const std::vector<uint8_t>& raw, size_t count, size_t stride, const char* mode, const char* filter) {
    std::vector<uint8_t> encoded;
    if (std::string(mode) == "ATTRIBUTES") {
      encoded.resize(meshopt_encodeVertexBufferBound(count, stride));
      encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), raw.data(), count, stride));
    } else {
      std::vector<uint32_t> indices(count);
      for (size_t i = 0; i < count; ++i) {
        uint16_t v;
        std::memcpy(&v, raw.data() + 2 * i, 2);
        indices[i] = v;
      }
      encoded.resize(meshopt_encodeIndexBufferBound(count, 65536));
      encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), indices.data(), count));
    }
    const int dataView = file.addView(encoded);
    const json& data = file.json["bufferViews"][size_t(dataView)];
    json view = {{"buffer", 1}, {"byteOffset", fallbackBytes}, {"byteLength", raw.size()}};
    if (std::string(mode) == "ATTRIBUTES") view["byteStride"] = stride;
    view["extensions"]["EXT_meshopt_compression"] = {{"buffer", 0},
                                                     {"byteOffset", data["byteOffset"]},
                                                     {"byteLength", data["byteLength"]},
                                                     {"byteStride", stride},
                                                     {"count", count},
                                                     {"mode", mode}};
    if (std::string(filter) != "NONE") view["extensions"]["EXT_meshopt_compression"]["filter"] = filter;
    fallbackBytes = (fallbackBytes + raw.size() + 3) / 4 * 4;
    file.json["bufferViews"].push_back(view);
    return int(file.json["bufferViews"].size()) - 1;
  }
};

// As gltfpack writes it; returns the primitive and sets `nodeScale` (uniform) and `nodeOffset`,
// which map the 16-bit positions back to the sphere's.
json meshoptPrimitive(GltfBuilder& file, const SphereMesh& sphere, float& nodeScale, glm::vec3& nodeOffset) {
  const size_t n = sphere.positions.size();
  nodeOffset = glm::vec3(-1.0f);
  nodeScale = 2.0f / 65535.0f;
  std::vector<uint16_t> positions;
  std::vector<float> normals;
  std::vector<uint16_t> uvs;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 q = glm::round((sphere.positions[i] - nodeOffset) / nodeScale);
    positions.insert(positions.end(), {uint16_t(q.x), uint16_t(q.y), uint16_t(q.z), 0});
    normals.insert(normals.end(), {sphere.normals[i].x, sphere.normals[i].y, sphere.normals[i].z, 0.0f});
    uvs.insert(uvs.end(), {uint16_t(std::lround(sphere.uvs[i].x * 65535.0f)), uint16_t(std::lround(sphere.uvs[i].y * 65535.0f))});
  }
  std::vector<int16_t> octahedral(n * 4);
  meshopt_encodeFilterOct(octahedral.data(), n, 8, 16, normals.data());
  std::vector<uint16_t> indices(sphere.indices.begin(), sphere.indices.end());

  MeshoptStreams streams{file};
  const int positionView = streams.add(bytesOf(positions), n, 8, "ATTRIBUTES", "NONE");
  const int normalView = streams.add(bytesOf(octahedral), n, 8, "ATTRIBUTES", "OCTAHEDRAL");
  const int uvView = streams.add(bytesOf(uvs), n, 4, "ATTRIBUTES", "NONE");
  const int indexView = streams.add(bytesOf(indices), indices.size(), 2, "TRIANGLES", "NONE");
  file.json["buffers"].push_back(
      {{"byteLength", streams.fallbackBytes}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
  const int positionAccessor = file.addAccessor(positionView, kUnsignedShort, n, "VEC3");
  file.json["accessors"][size_t(positionAccessor)]["min"] = {0, 0, 0};
  file.json["accessors"][size_t(positionAccessor)]["max"] = {65535, 65535, 65535};
  file.useExtension("EXT_meshopt_compression", true);
  file.useExtension("KHR_mesh_quantization", true);
  return {{"attributes",
           {{"POSITION", positionAccessor},
            {"NORMAL", file.addAccessor(normalView, kShort, n, "VEC3", true)},
            {"TEXCOORD_0", file.addAccessor(uvView, kUnsignedShort, n, "VEC2", true)}}},
          {"indices", file.addAccessor(indexView, kUnsignedShort, indices.size(), "SCALAR")}};
}

}  // namespace

std::filesystem::path writeCompressedSphere(const std::filesystem::path& dir, Compression compression) {
  GltfBuilder file;
  const SphereMesh sphere = uvSphere(32, 16);
  addCheckerMaterial(file);
  json node = {{"name", "sphere"}, {"mesh", 0}};
  json primitive;
  const char* name = "compressed-plain";
  if (compression == Compression::None) {
    std::vector<uint16_t> indices(sphere.indices.begin(), sphere.indices.end());
    primitive = {{"attributes",
                  {{"POSITION", file.addFloats(flatten(sphere.positions), "VEC3", 3)},
                   {"NORMAL", file.addFloats(flatten(sphere.normals), "VEC3", 3)},
                   {"TEXCOORD_0", file.addFloats(flatten(sphere.uvs), "VEC2", 2)}}},
                 {"indices", file.addAccessor(file.addView(bytesOf(indices)), kUnsignedShort, indices.size(), "SCALAR")}};
  } else if (compression == Compression::Draco) {
    primitive = dracoPrimitive(file, sphere);
    name = "compressed-draco";
  } else {
    float scale = 1.0f;
    glm::vec3 offset(0.0f);
    primitive = meshoptPrimitive(file, sphere, scale, offset);
    node["translation"] = {offset.x, offset.y, offset.z};
    node["scale"] = {scale, scale, scale};
    name = "compressed-meshopt";
  }
  primitive["material"] = 0;
  file.json["meshes"] = {{{"name", "sphere"}, {"primitives", {primitive}}}};
  file.json["nodes"] = {node};
  addStage(file, {0.0f, 0.6f, 3.4f}, {0.0f, 0.0f, 0.0f}, {-1.0f, -0.6f, -0.8f}, 1500.0f, {0});
  return file.write(dir, name);
}

std::filesystem::path writeSparseGrid(const std::filesystem::path& dir, bool sparse) {
  constexpr int kColumns = 12;
  constexpr int kRows = 6;
  GltfBuilder file;
  std::vector<glm::vec3> positions;
  for (int z = 0; z <= kRows; ++z) {
    for (int x = 0; x <= kColumns; ++x) positions.emplace_back(float(x) / 4.0f - 1.5f, 0.0f, float(z) / 4.0f - 0.75f);
  }
  // Two ridges across the grid, as SimpleSparseAccessor lifts some of its vertices.
  std::vector<uint16_t> lifted;
  std::vector<glm::vec3> liftedTo;
  for (int z = 0; z <= kRows; ++z) {
    for (int x : {3, 8}) {
      const uint16_t v = uint16_t(z * (kColumns + 1) + x);
      lifted.push_back(v);
      liftedTo.push_back(positions[v] + glm::vec3(0.0f, 0.5f, 0.0f));
    }
  }
  std::vector<uint16_t> indices;
  for (int z = 0; z < kRows; ++z) {
    for (int x = 0; x < kColumns; ++x) {
      const uint16_t a = uint16_t(z * (kColumns + 1) + x);
      const uint16_t b = uint16_t(a + kColumns + 1);
      indices.insert(indices.end(), {a, b, uint16_t(b + 1), a, uint16_t(b + 1), uint16_t(a + 1)});
    }
  }
  std::vector<glm::vec3> dense = positions;
  for (size_t i = 0; i < lifted.size(); ++i) dense[lifted[i]] = liftedTo[i];
  const int position = file.addFloats(flatten(sparse ? positions : dense), "VEC3", 3);
  json& accessor = file.json["accessors"][size_t(position)];
  if (sparse) {
    accessor["max"][1] = 0.5f;  // min and max describe the values after substitution
    accessor["sparse"] = {{"count", lifted.size()},
                          {"indices", {{"bufferView", file.addView(bytesOf(lifted))}, {"componentType", kUnsignedShort}}},
                          {"values", {{"bufferView", file.addView(bytesOf(flatten(liftedTo)))}}}};
  }
  file.json["materials"] = {{{"name", "grey"},
                             {"pbrMetallicRoughness", {{"baseColorFactor", {0.7, 0.7, 0.7, 1.0}}}},
                             {"doubleSided", true},
                             {"extras", {{"wavepath", {{"bsdf", "lambert"}}}}}}};
  const int index = file.addAccessor(file.addView(bytesOf(indices)), kUnsignedShort, indices.size(), "SCALAR");
  const json primitive = {{"attributes", {{"POSITION", position}}}, {"indices", index}, {"material", 0}};
  file.json["meshes"] = {{{"name", "grid"}, {"primitives", {primitive}}}};
  file.json["nodes"] = {{{"name", "grid"}, {"mesh", 0}}};
  addStage(file, {0.0f, 2.2f, 2.6f}, {0.0f, 0.0f, 0.0f}, {-1.0f, -0.5f, 0.2f}, 1500.0f, {0});
  return file.write(dir, sparse ? "sparse-grid" : "dense-grid");
}

std::filesystem::path writeMinificationPlane(const std::filesystem::path& dir) {
  GltfBuilder file;
  constexpr int kTexels = 8;
  std::vector<uint8_t> rgb;
  for (int i = 0; i < kTexels * kTexels; ++i) {
    const uint8_t v = (i % kTexels + i / kTexels) % 2 == 0 ? 230 : 20;
    rgb.insert(rgb.end(), {v, v, v});
  }
  file.json["images"] = {{{"bufferView", file.addView(encodePng(kTexels, kTexels, 3, rgb))}, {"mimeType", "image/png"}}};
  file.json["samplers"] = {{{"magFilter", 9729}, {"minFilter", 9987}}};
  file.json["textures"] = {{{"source", 0}, {"sampler", 0}}};
  file.json["materials"] = {{{"name", "checker"},
                             {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                             {"extras", {{"wavepath", {{"bsdf", "lambert"}}}}}}};
  // 200 m square, the texture repeated once a metre: a texel is 12.5 cm.
  constexpr float kHalf = 100.0f;
  const int position = file.addFloats({-kHalf, 0, -kHalf, -kHalf, 0, kHalf, kHalf, 0, kHalf, kHalf, 0, -kHalf}, "VEC3", 3);
  const int uv = file.addFloats({-kHalf, -kHalf, -kHalf, kHalf, kHalf, kHalf, kHalf, -kHalf}, "VEC2", 2);
  const int index = file.addAccessor(file.addView(bytesOf(std::vector<uint16_t>{0, 1, 2, 0, 2, 3})), kUnsignedShort, 6,
                                     "SCALAR");
  const json primitive = {{"attributes", {{"POSITION", position}, {"TEXCOORD_0", uv}}}, {"indices", index}, {"material", 0}};
  file.json["meshes"] = {{{"name", "ground"}, {"primitives", {primitive}}}};
  file.json["nodes"] = {{{"name", "ground"}, {"mesh", 0}},
                        {{"name", "camera"}, {"camera", 0}, {"translation", {0.0, 1.0, 0.0}},
                         {"rotation", rotationFromMinusZ({0.0f, -0.35f, -1.0f})}}};
  file.json["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.6}, {"znear", 0.01}}}}};
  file.json["scene"] = 0;
  file.json["scenes"] = {{{"nodes", {0, 1}}}};
  return file.write(dir, "minification");
}

namespace {

// A normal texture of ripples along u, as PNG bytes (tangent space: x = 0.5 + 0.4 sin).
std::vector<uint8_t> ripplePng() {
  constexpr int kSize = 32;
  std::vector<uint8_t> rgb;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const float slope = 0.4f * std::sin(2.0f * std::numbers::pi_v<float> * 4.0f * float(x) / float(kSize));
      const glm::vec3 n = glm::normalize(glm::vec3(slope, 0.0f, 1.0f)) * 0.5f + 0.5f;
      rgb.insert(rgb.end(), {uint8_t(n.x * 255.0f + 0.5f), uint8_t(n.y * 255.0f + 0.5f), uint8_t(n.z * 255.0f + 0.5f)});
    }
  }
  return encodePng(kSize, kSize, 3, rgb);
}

// The extension's name after "KHR_materials_".
const char* shortName(MaterialExtension extension) {
  switch (extension) {
    case MaterialExtension::Specular: return "specular";
    case MaterialExtension::Sheen: return "sheen";
    case MaterialExtension::Clearcoat: return "clearcoat";
    case MaterialExtension::Unlit: break;
  }
  return "unlit";
}

// Sphere `i` of four: its material's base (pbrMetallicRoughness) and its extension object.
json sphereMaterial(GltfBuilder& file, MaterialExtension extension, int i) {
  const double step = double(i) / 3.0;
  json base = {{"baseColorFactor", {0.1, 0.15, 0.6, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.3}};
  json object;
  switch (extension) {
    case MaterialExtension::Specular:
      object = {{"specularFactor", step}, {"specularColorFactor", {1.0, 0.6, 0.2}}};
      break;
    case MaterialExtension::Sheen:
      base = {{"baseColorFactor", {0.05, 0.05, 0.2, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.8}};
      object = {{"sheenColorFactor", {1.0, 0.6, 0.8}}, {"sheenRoughnessFactor", 0.2 + 0.2 * i}};
      break;
    case MaterialExtension::Clearcoat:
      base = {{"baseColorFactor", {0.7, 0.05, 0.05, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.7}};
      object = {{"clearcoatFactor", 1.0}, {"clearcoatRoughnessFactor", 0.2 * i}};
      if (i == 3) {
        file.json["images"] = {{{"bufferView", file.addView(ripplePng())}, {"mimeType", "image/png"}}};
        file.json["textures"] = {{{"source", 0}}};
        object["clearcoatRoughnessFactor"] = 0.05;
        object["clearcoatNormalTexture"] = {{"index", 0}, {"scale", 1.0}};
      }
      break;
    case MaterialExtension::Unlit:
      base = {{"baseColorFactor", {0.9 - 0.25 * i, 0.3 + 0.2 * i, 0.2, 1.0}}};
      object = json::object();
      break;
  }
  return {{"pbrMetallicRoughness", base},
          {"extensions", {{std::string("KHR_materials_") + shortName(extension), object}}}};
}

}  // namespace

std::filesystem::path writeMaterialSpheres(const std::filesystem::path& dir, MaterialExtension extension,
                                           bool withExtension) {
  GltfBuilder file;
  const SphereMesh sphere = uvSphere(48, 24);
  std::vector<uint16_t> indices(sphere.indices.begin(), sphere.indices.end());
  const json attributes = {{"POSITION", file.addFloats(flatten(sphere.positions), "VEC3", 3)},
                           {"NORMAL", file.addFloats(flatten(sphere.normals), "VEC3", 3)},
                           {"TEXCOORD_0", file.addFloats(flatten(sphere.uvs), "VEC2", 2)}};
  const int index = file.addAccessor(file.addView(bytesOf(indices)), kUnsignedShort, indices.size(), "SCALAR");
  const std::string name = shortName(extension);
  std::vector<int> nodes;
  for (int i = 0; i < 4; ++i) {
    json material = sphereMaterial(file, extension, i);
    if (!withExtension) material.erase("extensions");
    material["name"] = name + " " + std::to_string(i);
    file.json["materials"].push_back(material);
    file.json["meshes"].push_back({{"primitives", {{{"attributes", attributes}, {"indices", index}, {"material", i}}}}});
    file.json["nodes"].push_back({{"mesh", i}, {"translation", {2.3 * (i - 1.5), 0.0, 0.0}}});
    nodes.push_back(i);
  }
  if (withExtension) file.useExtension("KHR_materials_" + name, false);
  addStage(file, {0.0f, 1.5f, 7.5f}, {0.0f, 0.0f, 0.0f}, {-0.6f, -0.8f, -0.5f}, 1500.0f, nodes);
  return file.write(dir, name + "-spheres" + (withExtension ? "" : "-without"));
}

void writeAllSamples(const std::filesystem::path& dir) {
  writeMinificationPlane(dir);
  writeAlphaCoverage(dir);
  writeAlphaShadow(dir);
  writeTextureTransform(dir);
  for (MaterialExtension e : {MaterialExtension::Specular, MaterialExtension::Sheen, MaterialExtension::Clearcoat,
                              MaterialExtension::Unlit}) {
    writeMaterialSpheres(dir, e, true);
  }
  for (Compression c : {Compression::None, Compression::Draco, Compression::Meshopt}) writeCompressedSphere(dir, c);
  writeSparseGrid(dir, true);
  writeSparseGrid(dir, false);
}

}  // namespace wp::samples
