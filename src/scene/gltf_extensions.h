// The glTF extensions wavepath understands, and the check of a file's extension lists.
#pragma once

#include <array>
#include <string_view>

#include "scene/gltf_context.h"

namespace wp::gltf {

// Every extension the loader implements. Add an entry here when the loader learns one.
inline constexpr std::array<std::string_view, 5> kSupportedExtensions{
    "KHR_lights_punctual",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_transmission",
    "KHR_materials_volume",
};

// Throws when extensionsRequired names an extension outside kSupportedExtensions; warns
// once, listing them, about unsupported entries of extensionsUsed.
void checkExtensions(const Context& ctx);

}  // namespace wp::gltf
