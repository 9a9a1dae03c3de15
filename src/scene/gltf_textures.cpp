// glTF textures (image plus sampler) to wavepath textures.
#include "scene/gltf_textures.h"

#include <cstring>
#include <string>
#include <string_view>
#include <utility>

#include "core/error.h"
#include "scene/gltf_extensions.h"

namespace wp::gltf {

namespace {

constexpr const char* kWebp = "EXT_texture_webp";

Texture::Wrap wrapOf(int mode) {
  if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return Texture::Wrap::Clamp;
  if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return Texture::Wrap::Mirror;
  return Texture::Wrap::Repeat;  // glTF's default
}

bool validImage(const tinygltf::Model& model, int image) {
  return image >= 0 && static_cast<size_t>(image) < model.images.size();
}

// The `source` of texture extension `ext`, -1 when absent or not a valid image index.
int extensionSource(const tinygltf::Model& model, const tinygltf::Texture& texture, const std::string& ext) {
  const auto it = texture.extensions.find(ext);
  if (it == texture.extensions.end() || !it->second.Has("source") || !it->second.Get("source").IsInt()) return -1;
  const int source = it->second.Get("source").GetNumberAsInt();
  return validImage(model, source) ? source : -1;
}

// The first of kFallbackImageExtensions that texture has, with its image; {"", -1} if none.
std::pair<std::string, int> undecodableSource(const tinygltf::Model& model, const tinygltf::Texture& texture) {
  for (const std::string_view ext : kFallbackImageExtensions) {
    if (const int image = extensionSource(model, texture, std::string(ext)); image >= 0) return {std::string(ext), image};
  }
  return {"", -1};
}

// The image texture `index` shows: its WebP one, else its `source`. Throws, naming the
// extension and image, when only a format wavepath cannot decode is left.
int resolveImage(const Context& ctx, size_t index) {
  const tinygltf::Model& model = ctx.model;
  const tinygltf::Texture& texture = model.textures[index];
  if (const int webp = extensionSource(model, texture, kWebp); webp >= 0) return webp;
  if (validImage(model, texture.source)) return texture.source;
  const std::string where = describe("texture", index, texture.name);
  if (const auto [ext, image] = undecodableSource(model, texture); image >= 0) {
    fail(ctx, where,
         "its only image, " + describeImage(model, image) + ", is for " + ext +
             ", which wavepath cannot decode (Debian has no decoder for it); re-export the scene with PNG, JPEG or "
             "WebP textures, or with them as fallbacks");
  }
  fail(ctx, where,
       "has no image it can use (source " + std::to_string(texture.source) + "); re-export the file");
}

}  // namespace

std::string describeImage(const tinygltf::Model& model, int index) {
  const tinygltf::Image& image = model.images[static_cast<size_t>(index)];
  std::string out = describe("image", static_cast<size_t>(index), image.name);
  if (image.bufferView >= 0) return out + " (buffer view " + std::to_string(image.bufferView) + ")";
  // tinygltf keeps the uri of a file only.
  if (image.uri.empty() || image.uri.rfind("data:", 0) == 0) return out + " (a data: URI)";
  return out + " ('" + oneLine(image.uri.substr(0, 200)) + "')";
}

TextureTable::TextureTable(const Context& ctx, std::vector<Texture>& textures) : ctx_(ctx), textures_(textures) {
  std::string fallbackExtension;
  size_t fallbacks = 0;
  for (size_t t = 0; t < ctx.model.textures.size(); ++t) {
    imageOf_.push_back(resolveImage(ctx, t));
    const auto [ext, image] = undecodableSource(ctx.model, ctx.model.textures[t]);
    if (image >= 0 && image != imageOf_.back()) fallbackExtension = ext, ++fallbacks;
  }
  if (fallbacks > 0) {
    warnAt(ctx, "", std::to_string(fallbacks) + " of " + std::to_string(ctx.model.textures.size()) +
                        " textures have images for " + fallbackExtension +
                        ", which wavepath cannot decode: they show their fallback images");
  }
}

const Rgba8Image& TextureTable::decoded(int index, const std::string& where) {
  if (const auto known = decoded_.find(index); known != decoded_.end()) return known->second;
  const tinygltf::Image& image = ctx_.model.images[static_cast<size_t>(index)];
  if (!image.as_is || image.image.empty()) {
    // tinygltf only warns about an image file it cannot find, and leaves the image empty.
    fail(ctx_, where, describeImage(ctx_.model, index) + " could not be read; check that the file is beside the scene");
  }
  try {
    return decoded_[index] = decodeTexture(image.image.data(), image.image.size());
  } catch (const Error& e) {
    fail(ctx_, where,
         describeImage(ctx_.model, index) + " cannot be decoded (" + e.what() + "); use PNG, JPEG or WebP");
  }
}

int TextureTable::add(int index, bool srgb, const std::string& where) {
  const auto key = std::make_pair(index, srgb);
  if (const auto it = converted_.find(key); it != converted_.end()) return it->second;
  const auto& model = ctx_.model;
  if (index < 0 || static_cast<size_t>(index) >= model.textures.size()) {
    fail(ctx_, where, "texture " + missingIndex(index, model.textures.size(), "textures") + "; re-export the file");
  }
  const tinygltf::Texture& gltfTexture = model.textures[static_cast<size_t>(index)];
  const Rgba8Image& image =
      decoded(imageOf_[static_cast<size_t>(index)], where + ": " + describe("texture", size_t(index), gltfTexture.name));
  Texture texture;
  texture.width = image.width;
  texture.height = image.height;
  texture.rgba.resize(size_t(texture.width) * texture.height);
  std::memcpy(texture.rgba.data(), image.rgba.data(), image.rgba.size());  // r in the low byte
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
