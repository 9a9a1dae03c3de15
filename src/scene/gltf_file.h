// Reading a .gltf or .glb file into a tinygltf model, with one-line errors.
#pragma once

#include <filesystem>

#include <tiny_gltf.h>

namespace wp::gltf {

// Parses `file` (JSON .gltf with external or data: buffers, or binary .glb, told apart by
// the "glTF" magic). Throws wp::Error with one line for a missing, unreadable or malformed
// file, buffer or image (decoded to RGBA8 by decodePngOrJpeg); prints tinygltf's warnings
// with wp::warn, one per line.
tinygltf::Model parseGltfFile(const std::filesystem::path& file);

}  // namespace wp::gltf
