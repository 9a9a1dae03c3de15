// KHR_materials_variants: the material a primitive shows in a variant the user chose.
#pragma once

#include <string>

#include "scene/gltf_context.h"

namespace wp::gltf {

// The index of the variant called `name` in the file's KHR_materials_variants list; -1 for an
// empty name (the default materials). Throws, listing the variants the file has, when it
// has none of that name.
int findVariant(const Context& ctx, const std::string& name);

// The material `primitive` shows in `variant` (from findVariant): the mapping's material
// where one of its mappings names the variant, else the primitive's own (glTF: a primitive
// without a mapping for a variant keeps its default material).
int variantMaterial(const Context& ctx, const tinygltf::Primitive& primitive, int variant, const std::string& where);

}  // namespace wp::gltf
