// Loading a glTF 2.0 file (.gltf or .glb) into a wavepath scene.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace wp {

struct LoadOptions {
  // Light the scene by chooseDefaultLighting (default_lighting.h), saying how with wp::note;
  // off when the caller brings a sky of its own.
  bool defaultSky = true;
  std::optional<size_t> scene;  // the glTF scene to load (--scene); default: the file's default
  // The camera to look through (--camera): a camera's index in the file, or the name of a
  // camera or of a node that places one; empty: the first camera of the scene's walk.
  std::string camera;
  // KHR_materials_variants: the variant whose materials to show (--variant); empty: the
  // file's default materials.
  std::string variant;
};

// Loads a scene of a .gltf (external buffers or embedded data: URIs) or .glb file: triangle
// meshes (one wp::Mesh per glTF mesh, one MeshInstance per node using it), materials,
// KHR_lights_punctual lights, a perspective or orthographic camera, and wavepath's analytic
// spheres and planes from node extras (schema in gltf_loader.cpp). Frames the scene
// automatically when it has no camera. Throws wp::Error with one line (what, where, what to
// do) for any file it cannot render; never crashes or hangs on bad input.
Scene loadScene(const std::filesystem::path& file, const LoadOptions& options = {});

}  // namespace wp
