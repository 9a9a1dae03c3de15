// A small glTF 2.0 writer for the sample files: JSON through nlohmann, one binary buffer.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace wp::samples {

constexpr int kByte = 5120;
constexpr int kUnsignedByte = 5121;
constexpr int kShort = 5122;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;

template <typename T>
std::vector<uint8_t> bytesOf(const std::vector<T>& values) {
  std::vector<uint8_t> bytes(values.size() * sizeof(T));
  if (!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

// Buffer 0 is the binary data, written as <name>.bin beside <name>.gltf. Everything else
// (meshes, materials, nodes, ...) is added to `json` directly.
class GltfBuilder {
public:
  GltfBuilder();

  // Appends `bytes` (4-byte aligned) to buffer 0 and a view of them; returns the view.
  int addView(const std::vector<uint8_t>& bytes, size_t byteStride = 0);
  // Appends an accessor; `view` -1 leaves it without a buffer view. Returns its index.
  int addAccessor(int view, int componentType, size_t count, const char* type, bool normalized = false,
                  size_t byteOffset = 0);
  // A FLOAT accessor with its own view, with min and max (required for POSITION).
  int addFloats(const std::vector<float>& values, const char* type, int components);
  // Appends `name` to extensionsUsed, and to extensionsRequired when `required`.
  void useExtension(const std::string& name, bool required);
  // Writes <dir>/<name>.gltf and <dir>/<name>.bin; returns the .gltf path.
  std::filesystem::path write(const std::filesystem::path& dir, const std::string& name);

  nlohmann::json json;
  std::vector<uint8_t> blob;
};

}  // namespace wp::samples
