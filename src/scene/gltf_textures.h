// glTF textures (image plus sampler) to wavepath textures.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "image/texture_decoder.h"
#include "scene/gltf_context.h"
#include "scene/scene.h"

namespace wp::gltf {

// Converts each glTF texture a material uses once per colour space (a texture used as both
// base colour and metallic-roughness becomes two), appending to `textures`. Its image is the
// EXT_texture_webp source where there is one, else `source`: the fallback of textures that
// also have a KTX2 (KHR_texture_basisu) or other image wavepath cannot decode. Images are
// decoded here, each once, after checkExtensions.
class TextureTable {
public:
  // Throws, naming the extension and the image, for a texture that has no image wavepath
  // can decode (only a KTX2 one, say), before any image is decoded.
  TextureTable(const Context& ctx, std::vector<Texture>& textures);

  // The index in `textures` of glTF texture `index`; throws when it or its image or
  // sampler does not exist, or its image cannot be read or decoded (naming the image file).
  int add(int index, bool srgb, const std::string& where);

private:
  const Rgba8Image& decoded(int image, const std::string& where);

  const Context& ctx_;
  std::vector<Texture>& textures_;
  std::vector<int> imageOf_;  // per glTF texture: the image it shows
  std::map<std::pair<int, bool>, int> converted_;
  std::map<int, Rgba8Image> decoded_;
};

// "image 2 ('wood.webp')", "image 2 (a data: URI)" or "image 2 (buffer view 7)", with the
// image's name where it has one: which image, in words that find it in the file.
std::string describeImage(const tinygltf::Model& model, int image);

}  // namespace wp::gltf
