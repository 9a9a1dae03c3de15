// Sample glTF files for what a surface's texture lookups and alpha do: alphaMode MASK and
// BLEND (cut-outs and see-through panes, seen by the camera and by shadow rays), and
// texture coordinate sets with KHR_texture_transform.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "samples/gltf_builder.h"
#include "samples/gltf_samples.h"

namespace wp::samples {

namespace {

using nlohmann::json;

constexpr int kNearest = 9728;

// A quad with corners a, b, c, d (counter-clockwise seen from its front) and uvs (0, 0),
// (0, 1), (1, 1), (1, 0) at them (TEXCOORD_0, or with `uvSet1` TEXCOORD_1 while TEXCOORD_0
// is (0.1, 0.1) everywhere), as a node of its own mesh; `colors` adds COLOR_0 (RGBA FLOAT,
// the same at every corner). Returns the node.
int addQuad(GltfBuilder& file, const std::string& name, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
            int material, const glm::vec4* color = nullptr, bool uvSet1 = false) {
  json attributes = {{"POSITION", file.addFloats({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z}, "VEC3", 3)},
                     {uvSet1 ? "TEXCOORD_1" : "TEXCOORD_0", file.addFloats({0, 0, 0, 1, 1, 1, 1, 0}, "VEC2", 2)}};
  if (uvSet1) attributes["TEXCOORD_0"] = file.addFloats(std::vector<float>(8, 0.1f), "VEC2", 2);
  if (color != nullptr) {
    std::vector<float> colors;
    for (int k = 0; k < 4; ++k) colors.insert(colors.end(), {color->r, color->g, color->b, color->a});
    attributes["COLOR_0"] = file.addFloats(colors, "VEC4", 4);
  }
  const int indices = file.addAccessor(file.addView(bytesOf(std::vector<uint16_t>{0, 1, 2, 0, 2, 3})), kUnsignedShort,
                                       6, "SCALAR");
  json& meshes = file.json["meshes"];
  meshes.push_back({{"name", name}, {"primitives", {{{"attributes", attributes}, {"indices", indices}, {"material", material}}}}});
  json& nodes = file.json["nodes"];
  nodes.push_back({{"name", name}, {"mesh", int(meshes.size()) - 1}});
  return int(nodes.size()) - 1;
}

// An orthographic camera at `position` with the glTF `rotation`, seeing 2 x 1 units.
int addTopCamera(GltfBuilder& file, glm::vec3 position, const std::vector<float>& rotation) {
  file.json["cameras"] = {{{"type", "orthographic"},
                           {"orthographic", {{"xmag", 1.0}, {"ymag", 0.5}, {"znear", 0.01}, {"zfar", 100.0}}}}};
  json& nodes = file.json["nodes"];
  nodes.push_back({{"name", "camera"}, {"camera", 0}, {"translation", {position.x, position.y, position.z}},
                   {"rotation", rotation}});
  return int(nodes.size()) - 1;
}

json lambert(const std::string& name, const std::vector<double>& baseColor) {
  return {{"name", name},
          {"pbrMetallicRoughness", {{"baseColorFactor", baseColor}}},
          {"doubleSided", true},
          {"extras", {{"wavepath", {{"bsdf", "lambert"}}}}}};
}

}  // namespace

std::filesystem::path writeAlphaCoverage(const std::filesystem::path& dir) {
  GltfBuilder file;
  constexpr int kTexels = 4;
  std::vector<uint8_t> rgba;
  for (int y = 0; y < kTexels; ++y) {
    for (int x = 0; x < kTexels; ++x) rgba.insert(rgba.end(), {0, 0, 0, uint8_t((x + y) % 2 == 0 ? 255 : 0)});
  }
  file.json["images"] = {{{"bufferView", file.addView(encodePng(kTexels, kTexels, 4, rgba))}, {"mimeType", "image/png"}}};
  file.json["samplers"] = {{{"magFilter", kNearest}, {"minFilter", kNearest}}};
  file.json["textures"] = {{{"source", 0}, {"sampler", 0}}};
  json mask = lambert("mask", {1, 1, 1, 1});
  mask["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  mask["alphaMode"] = "MASK";
  json blend = lambert("blend", {0, 0, 0, 0.5});
  blend["alphaMode"] = "BLEND";
  json emitter = lambert("emitter", {0, 0, 0, 1});
  emitter["emissiveFactor"] = {1, 1, 1};
  emitter["doubleSided"] = false;
  file.json["materials"] = {mask, blend, emitter};
  const glm::vec4 halfAlpha(1.0f, 1.0f, 1.0f, 0.5f);
  const std::vector<int> nodes = {
      addQuad(file, "mask", {-2, 1, 0}, {-2, -1, 0}, {0, -1, 0}, {0, 1, 0}, 0),
      addQuad(file, "blend", {0, 1, 0}, {0, -1, 0}, {2, -1, 0}, {2, 1, 0}, 1, &halfAlpha),
      addQuad(file, "emitter", {-3, 2, -1}, {-3, -2, -1}, {3, -2, -1}, {3, 2, -1}, 2),
      addTopCamera(file, {0, 0, 5}, {0, 0, 0, 1})};
  file.json["cameras"][0]["orthographic"]["xmag"] = 2.0;
  file.json["cameras"][0]["orthographic"]["ymag"] = 1.0;
  file.json["scene"] = 0;
  file.json["scenes"] = {{{"nodes", nodes}}};
  return file.write(dir, "alpha-coverage");
}

std::filesystem::path writeAlphaShadow(const std::filesystem::path& dir) {
  GltfBuilder file;
  json pane = lambert("pane", {0, 0, 0, 0.25});
  pane["alphaMode"] = "BLEND";
  file.json["materials"] = {lambert("floor", {0.8, 0.8, 0.8, 1}), pane};
  std::vector<int> nodes = {addQuad(file, "floor", {-2, 0, -1}, {-2, 0, 1}, {3, 0, 1}, {3, 0, -1}, 0),
                            addQuad(file, "pane", {-2, 1, -2}, {-2, 1, 2}, {0, 1, 2}, {0, 1, -2}, 1),
                            addTopCamera(file, {1, 3, 0}, rotationFromMinusZ({0, -1, 0}))};  // image top at -z
  file.json["nodes"].push_back({{"name", "sun"},
                                {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}},
                                {"rotation", rotationFromMinusZ({1, -1, 0})}});
  nodes.push_back(int(file.json["nodes"].size()) - 1);
  file.json["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "directional"}, {"intensity", 1000.0}}};
  file.useExtension("KHR_lights_punctual", false);
  file.json["scene"] = 0;
  file.json["scenes"] = {{{"nodes", nodes}}};
  return file.write(dir, "alpha-shadow");
}

std::filesystem::path writeTextureTransform(const std::filesystem::path& dir) {
  GltfBuilder file;
  std::vector<uint8_t> rgb;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const glm::u8vec3 t = transformTestTexel(x, y);
      rgb.insert(rgb.end(), {t.r, t.g, t.b});
    }
  }
  file.json["images"] = {{{"bufferView", file.addView(encodePng(4, 4, 3, rgb))}, {"mimeType", "image/png"}}};
  file.json["samplers"] = {{{"magFilter", kNearest}, {"minFilter", kNearest}}};
  file.json["textures"] = {{{"source", 0}, {"sampler", 0}}};
  const auto emitter = [](const std::string& name, const json& textureInfo) {
    return json{{"name", name},
                {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}},
                {"emissiveFactor", {1, 1, 1}},
                {"emissiveTexture", textureInfo}};
  };
  const json transformed = {{"index", 0},
                            {"extensions",
                             {{"KHR_texture_transform",
                               {{"offset", {kTransformOffset.x, kTransformOffset.y}},
                                {"rotation", kTransformRotation},
                                {"scale", {kTransformScale.x, kTransformScale.y}}}}}}};
  const json secondSet = {{"index", 0},
                          {"texCoord", 1},
                          {"extensions",
                           {{"KHR_texture_transform", {{"offset", {kSecondSetOffset.x, kSecondSetOffset.y}}}}}}};
  file.json["materials"] = {emitter("transformed", transformed), emitter("second set", secondSet)};
  file.useExtension("KHR_texture_transform", true);
  const std::vector<int> nodes = {
      addQuad(file, "transformed", {-2, 1, 0}, {-2, -1, 0}, {0, -1, 0}, {0, 1, 0}, 0),
      addQuad(file, "second set", {0, 1, 0}, {0, -1, 0}, {2, -1, 0}, {2, 1, 0}, 1, nullptr, true),
      addTopCamera(file, {0, 0, 5}, {0, 0, 0, 1})};
  file.json["cameras"][0]["orthographic"]["xmag"] = 2.0;
  file.json["cameras"][0]["orthographic"]["ymag"] = 1.0;
  file.json["scene"] = 0;
  file.json["scenes"] = {{{"nodes", nodes}}};
  return file.write(dir, "texture-transform");
}

}  // namespace wp::samples
