// The glTF extensions wavepath understands, and the check of a file's extension lists.
#pragma once

#include <array>
#include <string_view>

#include "scene/gltf_context.h"

namespace wp::gltf {

// Every extension the loader implements. Add an entry here when the loader learns one.
inline constexpr std::array<std::string_view, 15> kSupportedExtensions{
    "EXT_meshopt_compression",
    "EXT_texture_webp",
    "KHR_draco_mesh_compression",
    "KHR_lights_punctual",
    "KHR_materials_clearcoat",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_sheen",
    "KHR_materials_specular",
    "KHR_materials_transmission",
    "KHR_materials_unlit",
    "KHR_materials_variants",
    "KHR_materials_volume",
    "KHR_mesh_quantization",
    "KHR_texture_transform",
};

// Texture extensions whose images wavepath cannot decode (Debian has no decoder for KTX2's
// Basis Universal, AVIF in glTF, or DDS): a texture shows its fallback `source` instead, and
// one without a fallback is an error that names the extension and the image (TextureTable).
inline constexpr std::array<std::string_view, 3> kFallbackImageExtensions{
    "KHR_texture_basisu",
    "EXT_texture_avif",
    "MSFT_texture_dds",
};

// Throws when extensionsRequired names an extension outside kSupportedExtensions and
// kFallbackImageExtensions; warns once, listing them, about unsupported entries of
// extensionsUsed (TextureTable warns about the textures that show their fallbacks).
void checkExtensions(const Context& ctx);

}  // namespace wp::gltf
