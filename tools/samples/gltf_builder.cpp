// A small glTF 2.0 writer for the sample files: JSON through nlohmann, one binary buffer.
#include "samples/gltf_builder.h"

#include <algorithm>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace wp::samples {

GltfBuilder::GltfBuilder() {
  json = {{"asset", {{"version", "2.0"}, {"generator", "wavepath-make-samples"}}},
          {"buffers", nlohmann::json::array({nlohmann::json::object()})},
          {"bufferViews", nlohmann::json::array()},
          {"accessors", nlohmann::json::array()}};
}

int GltfBuilder::addView(const std::vector<uint8_t>& bytes, size_t byteStride) {
  blob.resize((blob.size() + 3) / 4 * 4, 0);
  nlohmann::json view = {{"buffer", 0}, {"byteOffset", blob.size()}, {"byteLength", bytes.size()}};
  if (byteStride != 0) view["byteStride"] = byteStride;
  blob.insert(blob.end(), bytes.begin(), bytes.end());
  json["bufferViews"].push_back(view);
  return int(json["bufferViews"].size()) - 1;
}

int GltfBuilder::addAccessor(int view, int componentType, size_t count, const char* type, bool normalized,
                             size_t byteOffset) {
  nlohmann::json accessor = {{"componentType", componentType}, {"count", count}, {"type", type}};
  if (view >= 0) accessor["bufferView"] = view;
  if (byteOffset != 0) accessor["byteOffset"] = byteOffset;
  if (normalized) accessor["normalized"] = true;
  json["accessors"].push_back(accessor);
  return int(json["accessors"].size()) - 1;
}

int GltfBuilder::addFloats(const std::vector<float>& values, const char* type, int components) {
  const int index = addAccessor(addView(bytesOf(values)), kFloat, values.size() / size_t(components), type);
  std::vector<float> lo(size_t(components), std::numeric_limits<float>::max());
  std::vector<float> hi(size_t(components), std::numeric_limits<float>::lowest());
  for (size_t i = 0; i < values.size(); ++i) {
    lo[i % size_t(components)] = std::min(lo[i % size_t(components)], values[i]);
    hi[i % size_t(components)] = std::max(hi[i % size_t(components)], values[i]);
  }
  json["accessors"][size_t(index)]["min"] = lo;
  json["accessors"][size_t(index)]["max"] = hi;
  return index;
}

void GltfBuilder::useExtension(const std::string& name, bool required) {
  for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
    if (list == std::string("extensionsRequired") && !required) continue;
    nlohmann::json& names = json[list];
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
}

std::filesystem::path GltfBuilder::write(const std::filesystem::path& dir, const std::string& name) {
  std::filesystem::create_directories(dir);
  json["buffers"][0]["byteLength"] = blob.size();
  json["buffers"][0]["uri"] = name + ".bin";
  std::ofstream(dir / (name + ".bin"), std::ios::binary)
      .write(reinterpret_cast<const char*>(blob.data()), std::streamsize(blob.size()));
  const std::filesystem::path file = dir / (name + ".gltf");
  std::ofstream out(file);
  out << json.dump(1) << "\n";
  if (!out) throw std::runtime_error("cannot write " + file.string());
  return file;
}

}  // namespace wp::samples
