// libFuzzer target: any bytes as the one image of a textured quad in a .glb (base colour,
// emissive and normal texture), decoded as wavepath decodes PNG and JPEG textures.
#include <cstring>
#include <string>
#include <vector>

#include "fuzz_support.h"

namespace {

void append(std::vector<uint8_t>& out, const void* data, size_t size) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  out.insert(out.end(), bytes, bytes + size);
}

void appendWord(std::vector<uint8_t>& out, uint32_t word) { append(out, &word, 4); }

// A quad with TEXCOORD_0 whose material uses image 0, the bytes `image`, three ways.
std::vector<uint8_t> texturedQuadGlb(const uint8_t* image, size_t imageSize) {
  const float geometry[] = {-1, -1, -2, 1, -1, -2, 1, 1, -2, -1, 1, -2,  // POSITION
                            0,  0,  1,  0, 1,  1,  0, 1};                 // TEXCOORD_0
  const uint16_t indices[] = {0, 1, 2, 0, 2, 3};
  std::vector<uint8_t> bin;
  append(bin, geometry, sizeof(geometry));
  append(bin, indices, sizeof(indices));
  const size_t imageOffset = bin.size();
  append(bin, image, imageSize);
  while (bin.size() % 4 != 0) bin.push_back(0);
  const std::string json =
      "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1},\"indices\":2,\"material\":0}]}],"
      "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}},"
      "\"emissiveTexture\":{\"index\":0},\"emissiveFactor\":[1,1,1],\"normalTexture\":{\"index\":0}}],"
      "\"textures\":[{\"source\":0}],\"images\":[{\"bufferView\":3,\"mimeType\":\"image/png\"}],"
      "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"},"
      "{\"bufferView\":1,\"componentType\":5126,\"count\":4,\"type\":\"VEC2\"},"
      "{\"bufferView\":2,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"}],"
      "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":48},{\"buffer\":0,\"byteOffset\":48,\"byteLength\":32},"
      "{\"buffer\":0,\"byteOffset\":80,\"byteLength\":12},{\"buffer\":0,\"byteOffset\":" +
      std::to_string(imageOffset) + ",\"byteLength\":" + std::to_string(imageSize) + "}],\"buffers\":[{\"byteLength\":" +
      std::to_string(bin.size()) + "}]}";
  std::string paddedJson = json;
  while (paddedJson.size() % 4 != 0) paddedJson += ' ';
  std::vector<uint8_t> glb;
  append(glb, "glTF", 4);
  appendWord(glb, 2);
  appendWord(glb, uint32_t(12 + 8 + paddedJson.size() + 8 + bin.size()));
  appendWord(glb, uint32_t(paddedJson.size()));
  append(glb, "JSON", 4);
  append(glb, paddedJson.data(), paddedJson.size());
  appendWord(glb, uint32_t(bin.size()));
  append(glb, "BIN\0", 4);
  append(glb, bin.data(), bin.size());
  return glb;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;  // a buffer view must not be empty; that case is the glTF target's
  const std::vector<uint8_t> glb = texturedQuadGlb(data, size);
  wp::fuzz::loadAndCheck(wp::fuzz::writeInput("textured.glb", glb.data(), glb.size()));
  return 0;
}
