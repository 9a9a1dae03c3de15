// glTF textures (image plus sampler) to wavepath textures.
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "scene/gltf_context.h"
#include "scene/scene.h"

namespace wp::gltf {

// Converts each glTF texture a material uses once per colour space (a texture used as both
// base colour and metallic-roughness becomes two), appending to `textures`.
class TextureTable {
public:
  TextureTable(const Context& ctx, std::vector<Texture>& textures) : ctx_(ctx), textures_(textures) {}

  // The index in `textures` of glTF texture `index`; throws when it or its image or
  // sampler does not exist or the image was not decoded.
  int add(int index, bool srgb, const std::string& where);

private:
  const Context& ctx_;
  std::vector<Texture>& textures_;
  std::map<std::pair<int, bool>, int> converted_;
};

}  // namespace wp::gltf
