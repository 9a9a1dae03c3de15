// KHR_lights_punctual: the lights a glTF file declares, and the node that places each.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "scene/gltf_context.h"
#include "scene/scene.h"

namespace wp::gltf {

// The file's lights in its order, in wavepath's units (scene.h: intensity / 683), not yet
// placed. Throws, naming the light, on an unknown type, a colour or intensity that is not
// finite and >= 0, or spot cone angles outside 0 <= inner < outer <= pi/2. Notes once that
// `range` is ignored when a light has one.
std::vector<PunctualLight> readLights(const Context& ctx);

// The light node `node` places, or nothing; throws when its index is not one of the file's.
std::optional<size_t> nodeLight(const Context& ctx, size_t node);

}  // namespace wp::gltf
