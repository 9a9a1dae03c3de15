// Loading a glTF 2.0 file (.gltf or .glb) into a wavepath scene.
#pragma once

#include <filesystem>

#include "scene/scene.h"

namespace wp {

// Loads the default scene of a .gltf (external buffers or embedded data: URIs) or .glb
// file: triangle meshes (one wp::Mesh per glTF mesh, one MeshInstance per node using it),
// materials, the first perspective camera, and wavepath's analytic spheres and planes from
// node extras (schema in gltf_loader.cpp). Frames the scene automatically when it has no
// camera, and (with `defaultSky`, when the caller brings no sky of its own) lights it with a
// white sky when nothing in it emits light, saying so with wp::note. Throws wp::Error with
// one line (what, where, what to do) for any file it cannot render; never crashes or hangs
// on bad input.
Scene loadScene(const std::filesystem::path& file, bool defaultSky = true);

}  // namespace wp
