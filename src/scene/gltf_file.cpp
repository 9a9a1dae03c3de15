// Reading a .gltf or .glb file into a tinygltf model, with one-line errors.
#include "scene/gltf_file.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file_read.h"
#include "core/log.h"
#include "scene/gltf_context.h"

namespace wp::gltf {

namespace {

namespace fs = std::filesystem;

// tinygltf converts JSON extras and extensions recursively, so an absurdly nested file
// would overflow the stack; real files nest a handful of levels.
constexpr int kMaxJsonDepth = 256;

[[noreturn]] void fileError(const fs::path& file, const std::string& message) {
  throw Error(file.string() + ": " + message);
}

// tinygltf takes lengths as unsigned int, so no file it reads may hold more.
constexpr uint64_t kMaxFileBytes = std::numeric_limits<unsigned int>::max();

// tinygltf's file access, for the buffers and images a .gltf names by URI: through
// readRegularFile, so a URI naming a directory, FIFO or device, or a file too large, is
// refused before anything is allocated or anything blocks. The first refusal is kept to be
// said as wavepath says errors (tinygltf would only warn about an image).
struct UriReads {
  std::string refusal;
};

bool uriExists(const std::string& path, void*) {
  struct stat status {};
  return ::stat(path.c_str(), &status) == 0;
}

bool readUri(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  try {
    std::string label = "'";  // appended piecewise to dodge a GCC 12 -Wrestrict false positive
    label += oneLine(path);
    label += "'";
    *out = readRegularFile(path, label, kMaxFileBytes, "a buffer or image file (a URI must name a regular file)");
    return true;
  } catch (const Error& e) {
    auto* reads = static_cast<UriReads*>(user);
    if (reads->refusal.empty()) reads->refusal = e.what();
    *err += e.what();
    return false;
  }
}

bool hasBinaryMagic(const std::vector<unsigned char>& bytes) {
  return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

// The JSON text of a .gltf, or the JSON chunk of a .glb as far as the file holds it.
std::string_view jsonText(const std::vector<unsigned char>& bytes, bool binary) {
  const char* text = reinterpret_cast<const char*>(bytes.data());
  if (!binary) return {text, bytes.size()};
  if (bytes.size() < 20) return {};
  uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return {text + 20, std::min<size_t>(length, bytes.size() - 20)};
}

int maxNesting(std::string_view json) {
  int depth = 0;
  int maxDepth = 0;
  bool inString = false;
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      maxDepth = std::max(maxDepth, ++depth);
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return maxDepth;
}

// Meshopt encoders (gltfpack) leave the fallback buffer of EXT_meshopt_compression without
// data (no uri), which tinygltf refuses in a .gltf and fills with the BIN chunk in a .glb.
// No byte of it is read: every view on it is decoded from its compressed buffer instead
// (gltf_compression.cpp). So each such buffer is given one byte. Returns whether it changed any.
bool fillMeshoptFallbacks(nlohmann::json& json, bool binary) {
  if (!json.contains("buffers") || !json["buffers"].is_array()) return false;
  bool changed = false;
  nlohmann::json& buffers = json["buffers"];
  // In a .glb, buffer 0 without a uri is the BIN chunk.
  for (size_t b = binary ? 1 : 0; b < buffers.size(); ++b) {
    nlohmann::json& buffer = buffers[b];
    const bool fallback = buffer.is_object() && !buffer.contains("uri") &&
                          buffer.value("/extensions/EXT_meshopt_compression/fallback"_json_pointer, false);
    if (!fallback) continue;
    buffer["uri"] = "data:application/octet-stream;base64,AA==";
    buffer["byteLength"] = 1;
    changed = true;
  }
  return changed;
}

// The indices accessor of a KHR_draco_mesh_compression primitive has no buffer view, which
// tinygltf refuses; the Draco data holds the indices (gltf_compression.cpp reads them from
// there), so the primitive's reference to it is dropped. Returns whether it dropped any.
bool dropDracoIndices(nlohmann::json& json) {
  if (!json.contains("meshes") || !json["meshes"].is_array()) return false;
  bool changed = false;
  for (nlohmann::json& mesh : json["meshes"]) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
    for (nlohmann::json& primitive : mesh["primitives"]) {
      if (primitive.is_object() && primitive.contains("indices") &&
          primitive.contains("/extensions/KHR_draco_mesh_compression"_json_pointer)) {
        primitive.erase("indices");
        changed = true;
      }
    }
  }
  return changed;
}

// The file with its JSON adapted to what tinygltf 2.7 reads of compressed meshes (above);
// other files come back unchanged.
std::vector<unsigned char> adaptedForTinygltf(std::vector<unsigned char> bytes, bool binary) {
  const std::string_view text = jsonText(bytes, binary);
  if (text.find("EXT_meshopt_compression") == std::string_view::npos &&
      text.find("KHR_draco_mesh_compression") == std::string_view::npos) {
    return bytes;
  }
  nlohmann::json json = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
  if (!json.is_object()) return bytes;  // tinygltf says what is wrong with it
  const bool filled = fillMeshoptFallbacks(json, binary);
  if (!dropDracoIndices(json) && !filled) return bytes;
  std::string rewritten = json.dump();
  if (!binary) return {rewritten.begin(), rewritten.end()};
  rewritten.resize((rewritten.size() + 3) / 4 * 4, ' ');  // chunks are 4-byte aligned
  uint32_t jsonLength = 0;
  std::memcpy(&jsonLength, bytes.data() + 12, 4);
  const size_t rest = std::min<size_t>(size_t(20) + jsonLength, bytes.size());
  std::vector<unsigned char> out(bytes.begin(), bytes.begin() + 12);
  const auto put32 = [&out](size_t at, uint32_t value) { std::memcpy(out.data() + at, &value, 4); };
  out.resize(20);
  put32(12, static_cast<uint32_t>(rewritten.size()));
  std::memcpy(out.data() + 16, "JSON", 4);
  out.insert(out.end(), rewritten.begin(), rewritten.end());
  out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(rest), bytes.end());
  put32(8, static_cast<uint32_t>(out.size()));
  return out;
}

bool hasGlbExtension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".glb";
}

// Keeps every image's bytes (file, data URI or .glb buffer view alike: tinygltf hands them
// over) undecoded, in image->image with as_is set: TextureTable decodes those its textures
// use, after the file's extensions are checked, so that an image in a format wavepath cannot
// decode is named with its extension. `user` is the model being loaded: tinygltf hands an
// image's buffer view over without checking that the view lies inside its buffer (it read
// past it, found by fuzz_gltf), so that is checked first.
bool keepImageBytes(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                    const unsigned char* bytes, int size, void* user) {
  if (image->bufferView >= 0) {
    const auto* model = static_cast<const tinygltf::Model*>(user);
    // tinygltf has checked both indices before calling.
    const tinygltf::BufferView& view = model->bufferViews[static_cast<size_t>(image->bufferView)];
    const size_t bufferSize = model->buffers[static_cast<size_t>(view.buffer)].data.size();
    if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset ||
        view.byteLength > size_t(std::numeric_limits<int>::max())) {
      *err += "image " + std::to_string(index) + (image->name.empty() ? "" : " '" + image->name + "'") +
              ": its buffer view " + std::to_string(image->bufferView) + " (bytes " +
              std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
              ") reaches past its buffer (" + std::to_string(bufferSize) + " bytes)";
      return false;
    }
  }
  image->as_is = true;
  image->image.assign(bytes, bytes + std::max(size, 0));
  return true;
}

void warnEachLine(const fs::path& file, const std::string& text) {
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = oneLine(text.substr(start, end - start));
    if (!line.empty()) warn(file.string() + ": " + line);
    start = end + 1;
  }
}

}  // namespace

tinygltf::Model parseGltfFile(const fs::path& file) {
  std::vector<unsigned char> bytes =
      readRegularFile(file, file.string(), kMaxFileBytes, "a .gltf or .glb file");
  const bool binary = hasBinaryMagic(bytes);
  if (!binary && hasGlbExtension(file)) {
    fileError(file, "is not a binary glTF file (it does not start with \"glTF\"); re-export it");
  }
  if (maxNesting(jsonText(bytes, binary)) > kMaxJsonDepth) {
    fileError(file, "its JSON nests deeper than " + std::to_string(kMaxJsonDepth) +
                        " levels, which no real glTF file does; re-export it");
  }
  bytes = adaptedForTinygltf(std::move(bytes), binary);

  tinygltf::TinyGLTF parser;
  tinygltf::Model model;
  parser.SetImageLoader(keepImageBytes, &model);
  UriReads uriReads;
  parser.SetFsCallbacks({uriExists, tinygltf::ExpandFilePath, readUri, tinygltf::WriteWholeFile, &uriReads});
  std::string err;
  std::string warnings;
  const std::string baseDir = file.parent_path().string();
  const auto size = static_cast<unsigned int>(bytes.size());
  bool ok = false;
  try {
    ok = binary ? parser.LoadBinaryFromMemory(&model, &err, &warnings, bytes.data(), size, baseDir)
                : parser.LoadASCIIFromString(&model, &err, &warnings, reinterpret_cast<const char*>(bytes.data()),
                                             size, baseDir);
  } catch (const std::out_of_range&) {
    // tinygltf reads the first byte of a buffer or image with .at(0) before checking that
    // there is one (a .glb buffer of byteLength 0).
    fileError(file, "is not a valid glTF 2.0 file: a buffer or image in it is empty (byteLength 0?); re-export it");
  }
  if (!uriReads.refusal.empty()) fileError(file, uriReads.refusal);
  if (!ok) {
    // tinygltf sometimes reports a failure only in its warnings.
    const std::string reason = oneLine(err.empty() ? warnings : err);
    fileError(file, "is not a valid glTF 2.0 file: " + (reason.empty() ? "unknown problem" : reason) +
                        "; check that it is complete, and that the files it names are beside it");
  }
  // tinygltf also reports some recoverable problems in `err` while succeeding.
  warnEachLine(file, warnings);
  warnEachLine(file, err);
  return model;
}

}  // namespace wp::gltf
