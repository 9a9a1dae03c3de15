// glTF materials to wavepath materials.
#pragma once

#include <vector>

#include "scene/gltf_context.h"
#include "scene/scene.h"

namespace wp::gltf {

// One wp::Material per glTF material, at the same index: baseColorFactor gives baseColor and
// alpha, emissiveFactor times KHR_materials_emissive_strength gives emission. Throws on
// non-finite factors or a negative strength; warns once when textures are ignored.
std::vector<Material> convertMaterials(const Context& ctx);

// The glTF default material, for primitives and shapes that name none: white, one-sided.
Material defaultMaterial();

}  // namespace wp::gltf
