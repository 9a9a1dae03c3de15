// One glTF mesh (all its primitives) to one wavepath triangle mesh.
#pragma once

#include <cstddef>
#include <cstdint>

#include "scene/gltf_context.h"
#include "scene/scene.h"

namespace wp::gltf {

// Converts glTF mesh `index`: every triangle primitive (lists, strips and fans, indexed or
// not) is merged into one wp::Mesh with one material index per triangle, the glTF material
// index or `defaultMaterial` when the primitive names none. Points and lines, and primitives
// without POSITION, are skipped with one warning for the mesh, so the result may have no
// triangles. Throws on a missing material, an index out of range or a malformed accessor.
Mesh convertMesh(const Context& ctx, size_t index, uint32_t defaultMaterial);

}  // namespace wp::gltf
