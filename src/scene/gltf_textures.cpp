// glTF textures (image plus sampler) to wavepath textures.
#include "scene/gltf_textures.h"

#include <cstring>
#include <string>

namespace wp::gltf {

namespace {

Texture::Wrap wrapOf(int mode) {
  if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return Texture::Wrap::Clamp;
  if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return Texture::Wrap::Mirror;
  return Texture::Wrap::Repeat;  // glTF's default
}

}  // namespace

int TextureTable::add(int index, bool srgb, const std::string& where) {
  const auto key = std::make_pair(index, srgb);
  if (const auto it = converted_.find(key); it != converted_.end()) return it->second;
  const auto& model = ctx_.model;
  if (index < 0 || static_cast<size_t>(index) >= model.textures.size()) {
    fail(ctx_, where, "texture " + missingIndex(index, model.textures.size(), "textures") + "; re-export the file");
  }
  const tinygltf::Texture& gltfTexture = model.textures[static_cast<size_t>(index)];
  const int source = gltfTexture.source;
  if (source < 0 || static_cast<size_t>(source) >= model.images.size()) {
    fail(ctx_, where,
         "texture " + std::to_string(index) + " has no image it can use (source " + std::to_string(source) +
             "); re-export the file");
  }
  const tinygltf::Image& image = model.images[static_cast<size_t>(source)];
  if (image.width <= 0 || image.height <= 0 || image.component != 4 || image.bits != 8 ||
      image.image.size() != size_t(image.width) * size_t(image.height) * 4) {
    // tinygltf only warns about an image file it cannot find, and leaves the image empty.
    const bool file = !image.uri.empty() && image.uri.rfind("data:", 0) != 0;
    fail(ctx_, where,
         "image " + std::to_string(source) + (file ? " '" + oneLine(image.uri.substr(0, 200)) + "'" : "") +
             " of texture " + std::to_string(index) +
             " could not be read; check that the file is beside the scene and is a PNG or JPEG image");
  }
  Texture texture;
  texture.width = static_cast<uint32_t>(image.width);
  texture.height = static_cast<uint32_t>(image.height);
  texture.rgba.resize(size_t(texture.width) * texture.height);
  std::memcpy(texture.rgba.data(), image.image.data(), image.image.size());  // r in the low byte
  texture.srgb = srgb;
  if (gltfTexture.sampler >= 0) {
    if (static_cast<size_t>(gltfTexture.sampler) >= model.samplers.size()) {
      fail(ctx_, where,
           "texture " + std::to_string(index) + "'s sampler " +
               missingIndex(gltfTexture.sampler, model.samplers.size(), "samplers") + "; re-export the file");
    }
    const tinygltf::Sampler& sampler = model.samplers[static_cast<size_t>(gltfTexture.sampler)];
    texture.wrapS = wrapOf(sampler.wrapS);
    texture.wrapT = wrapOf(sampler.wrapT);
    texture.nearest = sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
  }
  const int added = static_cast<int>(textures_.size());
  textures_.push_back(std::move(texture));
  converted_[key] = added;
  return added;
}

}  // namespace wp::gltf
