// glTF materials to wavepath materials.
#pragma once

#include <vector>

#include "scene/gltf_context.h"
#include "scene/scene.h"

namespace wp::gltf {

// One wp::Material per glTF material, at the same index: the pbrMetallicRoughness factors,
// KHR_materials_ior, _transmission, _volume (attenuation) and emissiveFactor times
// KHR_materials_emissive_strength; extras.wavepath.bsdf = "lambert" for ideal diffuse; the
// base colour and metallic-roughness textures, appended to `textures`. Throws on non-finite
// factors, extension values out of range or broken textures; warns once when textures are
// ignored.
std::vector<Material> convertMaterials(const Context& ctx, std::vector<Texture>& textures);

// The glTF default material, for primitives and shapes that name none: white, one-sided.
Material defaultMaterial();

}  // namespace wp::gltf
