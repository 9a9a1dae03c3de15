// glTF textures (image plus sampler) to wavepath textures.
#pragma once

#include <array>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "image/texture_decoder.h"
#include "scene/gltf_context.h"
#include "scene/scene.h"

namespace wp::gltf {

// Converts each glTF texture a material uses once per colour space, texture coordinate set
// and KHR_texture_transform (a texture used as both base colour and metallic-roughness
// becomes two), appending to `textures`. Its image is the
// EXT_texture_webp source where there is one, else `source`: the fallback of textures that
// also have a KTX2 (KHR_texture_basisu) or other image wavepath cannot decode. Images are
// decoded here, each once, after checkExtensions.
class TextureTable {
public:
  // Throws, naming the extension and the image, for a texture that has no image wavepath
  // can decode (only a KTX2 one, say), before any image is decoded.
  TextureTable(const Context& ctx, std::vector<Texture>& textures);

  // The index in `textures` of a material slot's texture: glTF texture `index` looked up with
  // TEXCOORD_<texCoord>, through the KHR_texture_transform among `extensions` (whose own
  // texCoord wins); -1 for a set other than 0 and 1, which the caller warns about. Throws when
  // the texture or its image or sampler does not exist, its image cannot be read or decoded
  // (naming the image file), or the transform is malformed.
  int add(int index, int texCoord, const tinygltf::ExtensionMap& extensions, bool srgb, const std::string& where);

  // The same for a glTF textureInfo (TextureInfo, NormalTextureInfo, ...).
  template <typename Info>
  int add(const Info& info, bool srgb, const std::string& where) {
    return add(info.index, info.texCoord, info.extensions, srgb, where);
  }

private:
  using Key = std::tuple<int, bool, int, std::array<float, 6>>;  // texture, sRGB, set, transform


  const Rgba8Image& decoded(int image, const std::string& where);

  const Context& ctx_;
  std::vector<Texture>& textures_;
  std::vector<int> imageOf_;  // per glTF texture: the image it shows
  std::map<Key, int> converted_;
  std::map<int, Rgba8Image> decoded_;
};

// "image 2 ('wood.webp')", "image 2 (a data: URI)" or "image 2 (buffer view 7)", with the
// image's name where it has one: which image, in words that find it in the file.
std::string describeImage(const tinygltf::Model& model, int image);

}  // namespace wp::gltf
