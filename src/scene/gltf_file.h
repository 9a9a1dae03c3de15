// Reading a .gltf or .glb file into a tinygltf model, with one-line errors.
#pragma once

#include <filesystem>

#include <tiny_gltf.h>

namespace wp::gltf {

// Parses `file` (JSON .gltf with external or data: buffers, or binary .glb, told apart by
// the "glTF" magic). Throws wp::Error with one line for a missing, unreadable or malformed
// file or buffer, or an image file that cannot be read; prints tinygltf's warnings with
// wp::warn, one per line. Images are kept undecoded (as_is, their file's bytes in `image`):
// TextureTable decodes the ones the materials use. The JSON of files with compressed meshes
// is adapted to what tinygltf reads of them (see adaptedForTinygltf).
tinygltf::Model parseGltfFile(const std::filesystem::path& file);

}  // namespace wp::gltf
