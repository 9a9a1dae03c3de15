// Checkpoint files: a text header, raw float layers and a checksum, written atomically.
#include "render/checkpoint.h"

#include <xxhash.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <string_view>
#include <sstream>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"

namespace wp {

namespace {

static_assert(std::endian::native == std::endian::little, "checkpoints store little-endian floats as the host does");

constexpr char kMagic[] = "wavepath checkpoint";
constexpr size_t kChecksumBytes = 8;
// A layer of the file: `components` floats per pixel from `first` on of an accumulation layer.
struct FileLayer {
  const char* name;
  uint32_t accumulationLayer;  // WP_LAYER_*
  uint32_t first;
  uint32_t components;
  const char* type;
};
constexpr FileLayer kFileLayers[] = {
    {"radiance.sum", WP_LAYER_RADIANCE, 0, 3, "f32x3"},
    {"radiance.sumSquares", WP_LAYER_RADIANCE_SQUARES, 0, 3, "f32x3"},
    {"albedo.sum", WP_LAYER_ALBEDO_DEPTH, 0, 3, "f32x3"},
    {"depth.sum", WP_LAYER_ALBEDO_DEPTH, 3, 1, "f32"},
    {"normal.sum", WP_LAYER_NORMAL, 0, 3, "f32x3"},
    {"samples", WP_LAYER_RADIANCE, 3, 1, "f32"},
    {"stopped", WP_LAYER_RADIANCE_SQUARES, 3, 1, "f32"},
};
constexpr size_t kFileLayerCount = sizeof(kFileLayers) / sizeof(kFileLayers[0]);
constexpr uint64_t kBytesPerPixel = [] {
  uint64_t bytes = 0;
  for (const FileLayer& layer : kFileLayers) bytes += layer.components * sizeof(float);
  return bytes;
}();

std::string layerNames() {
  std::string names;
  for (const FileLayer& layer : kFileLayers) names += (names.empty() ? "" : ", ") + std::string(layer.name);
  return names;
}

[[noreturn]] void failRead(const std::filesystem::path& path, const std::string& reason) {
  throw Error("cannot resume from checkpoint '" + path.string() + "': " + reason);
}

}  // namespace

void writeCheckpoint(const std::filesystem::path& path, const Checkpoint& c) {
  const uint64_t pixels = c.region.pixels();
  std::ostringstream header;
  header << kMagic << "\nformat " << kCheckpointFormat << "\nscene-hash " << c.identity.sceneHash << "\nsettings "
         << c.identity.settings << "\nspp " << c.samplesPerPixel << "\nsamples " << c.firstSample << " "
         << c.endSample << "\nregion " << c.region.x0 << " " << c.region.y0 << " " << c.region.x1 << " "
         << c.region.y1 << "\npaths-done " << c.pathsDone << "\ndevice " << c.device << "\n";
  for (const FileLayer& layer : kFileLayers) header << "layer " << layer.name << " " << layer.type << " " << pixels << "\n";
  header << "end\n";
  const std::string text = header.str();
  std::vector<unsigned char> bytes(text.begin(), text.end());
  for (const FileLayer& layer : kFileLayers) {
    const std::vector<glm::vec4>& values = *c.accumulation.layers()[layer.accumulationLayer];
    if (values.size() != pixels) throw Error("internal: a checkpoint layer of " + std::to_string(values.size()) +
                                             " pixels for a region of " + std::to_string(pixels));
    const size_t at = bytes.size(), stride = layer.components * sizeof(float);
    bytes.resize(at + pixels * stride);
    for (uint64_t i = 0; i < pixels; ++i) std::memcpy(&bytes[at + i * stride], &values[i][int(layer.first)], stride);
  }
  const uint64_t checksum = XXH3_64bits(bytes.data(), bytes.size());
  const size_t at = bytes.size();
  bytes.resize(at + kChecksumBytes);
  std::memcpy(&bytes[at], &checksum, kChecksumBytes);
  writeFileAtomically(path, bytes, "checkpoint");
}

Checkpoint readCheckpoint(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) failRead(path, "it does not exist or cannot be read; check the path, or leave out --resume to start afresh");
  // The whole file, then its checksum stripped: the text before it is what was hashed.
  std::string all;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size > 0) {
    all.resize(size_t(size));
    in.read(all.data(), size);
  }
  if (!in) failRead(path, "it cannot be read; check the path and its permissions");
  const std::string_view bytes = all;
  const std::string magicLine = std::string(kMagic) + "\n";
  if (bytes.size() < magicLine.size() || std::memcmp(bytes.data(), magicLine.data(), magicLine.size()) != 0)
    failRead(path, "it is not a wavepath checkpoint; check the path");
  uint64_t stored = 0;
  if (bytes.size() >= kChecksumBytes) std::memcpy(&stored, &bytes[bytes.size() - kChecksumBytes], kChecksumBytes);
  if (bytes.size() < kChecksumBytes || XXH3_64bits(bytes.data(), bytes.size() - kChecksumBytes) != stored)
    failRead(path, "it is truncated or damaged (checksum mismatch); resume from an intact copy or start afresh "
                   "without --resume");
  all.resize(all.size() - kChecksumBytes);

  // The header: "key value" lines up to "end".
  const size_t end = all.find("\nend\n");
  if (end == std::string::npos) failRead(path, "its header has no end line (damaged)");
  std::istringstream header(all.substr(magicLine.size(), end + 1 - magicLine.size()));
  Checkpoint c;
  int format = 0;
  std::vector<std::string> layers, layerTypes;
  std::vector<uint64_t> layerSizes;
  std::string line;
  auto damaged = [&](const std::string& what) { failRead(path, "its " + what + " line is damaged"); };
  while (std::getline(header, line)) {
    const size_t space = line.find(' ');
    const std::string key = line.substr(0, space), value = space == std::string::npos ? "" : line.substr(space + 1);
    std::istringstream v(value);
    if (key == "format") {
      if (!(v >> format)) damaged(key);
      if (format > kCheckpointFormat)
        failRead(path, "it was written by a newer wavepath (format " + std::to_string(format) +
                           "); resume it with that version");
    } else if (key == "scene-hash") {
      c.identity.sceneHash = value;
    } else if (key == "settings") {
      c.identity.settings = value;
    } else if (key == "spp") {
      if (!(v >> c.samplesPerPixel)) damaged(key);
    } else if (key == "samples") {
      if (!(v >> c.firstSample >> c.endSample)) damaged(key);
    } else if (key == "region") {
      if (!(v >> c.region.x0 >> c.region.y0 >> c.region.x1 >> c.region.y1)) damaged(key);
    } else if (key == "paths-done") {
      if (!(v >> c.pathsDone)) damaged(key);
    } else if (key == "device") {
      c.device = value;
    } else if (key == "layer") {
      std::string name, type;
      uint64_t count = 0;
      if (!(v >> name >> type >> count)) damaged(key);
      layers.push_back(name);
      layerTypes.push_back(type);
      layerSizes.push_back(count);
    } else {
      failRead(path, "its header has an unknown line '" + key + "' (damaged, or from a newer wavepath)");
    }
  }
  if (format == 0) failRead(path, "its header has no format line (damaged)");
  if (c.region.x1 <= c.region.x0 || c.region.y1 <= c.region.y0 || c.firstSample >= c.endSample ||
      c.endSample > c.samplesPerPixel)
    failRead(path, "its header is inconsistent (region or samples); start afresh without --resume");
  const uint64_t pixels = c.region.pixels();
  if (c.region.x1 > (1u << 16) || c.region.y1 > (1u << 16) || pixels * kBytesPerPixel > all.size())
    failRead(path, "its region is larger than its layers (truncated or damaged)");
  if (c.pathsDone < pixels * c.firstSample || c.pathsDone > pixels * c.endSample)
    failRead(path, "its paths-done is outside its samples (damaged)");
  bool sameLayers = layers.size() == kFileLayerCount;
  for (size_t l = 0; sameLayers && l < kFileLayerCount; ++l)
    sameLayers = layers[l] == kFileLayers[l].name && layerTypes[l] == kFileLayers[l].type;
  if (!sameLayers)
    failRead(path, "it holds other layers than " + layerNames() +
                       " (from another version of wavepath); start afresh without --resume");
  c.accumulation = Accumulation::zeros(pixels);
  size_t at = end + 5;
  for (size_t l = 0; l < kFileLayerCount; ++l) {
    const FileLayer& layer = kFileLayers[l];
    const size_t stride = layer.components * sizeof(float);
    if (layerSizes[l] != pixels || all.size() - at < pixels * stride)
      failRead(path, "layer " + layers[l] + " does not hold one value per pixel of its region (damaged)");
    std::vector<glm::vec4>& values = *c.accumulation.layers()[layer.accumulationLayer];
    for (uint64_t i = 0; i < pixels; ++i) std::memcpy(&values[i][int(layer.first)], &all[at + i * stride], stride);
    at += pixels * stride;
  }
  if (at != all.size()) failRead(path, "it has bytes after its layers (damaged)");
  return c;
}

}  // namespace wp
