// One glTF mesh (all its primitives) to one wavepath triangle mesh.
#pragma once

#include <cstddef>
#include <cstdint>

#include "scene/gltf_context.h"
#include "scene/mesh_deformation.h"
#include "scene/scene.h"

namespace wp::gltf {

// Converts glTF mesh `index`: every triangle primitive (lists, strips and fans, indexed or
// not) is merged into one wp::Mesh with one material index per triangle, the glTF material
// index or `defaultMaterial` when the primitive names none. Points and lines, and primitives
// without POSITION, are skipped with one warning for the mesh, so the result may have no
// triangles. Throws on a missing material, an index out of range or a malformed accessor.
// With `deformation`, also reads the `morphTargets` morph targets' POSITION and NORMAL
// deltas (zero where a target lacks one) and JOINTS_0 with WEIGHTS_0 (normalised; zero
// weights where a primitive lacks them), aligned with the mesh's vertices; its rest
// vertices are left to the caller.
Mesh convertMesh(const Context& ctx, size_t index, uint32_t defaultMaterial, MeshDeformation* deformation = nullptr,
                 size_t morphTargets = 0);

}  // namespace wp::gltf
