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
const char* const kLayerNames[] = {"radiance.sum", "radiance.sumSquares"};

std::vector<glm::vec4>& layerOf(Accumulation& accumulation, int layer) {
  return layer == 0 ? accumulation.sum : accumulation.sumSquares;
}
const std::vector<glm::vec4>& layerOf(const Accumulation& accumulation, int layer) {
  return layer == 0 ? accumulation.sum : accumulation.sumSquares;
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
  for (const char* name : kLayerNames) header << "layer " << name << " f32x3 " << pixels << "\n";
  header << "end\n";
  const std::string text = header.str();
  std::vector<unsigned char> bytes(text.begin(), text.end());
  for (int layer = 0; layer < 2; ++layer) {
    const std::vector<glm::vec4>& values = layerOf(c.accumulation, layer);
    if (values.size() != pixels) throw Error("internal: a checkpoint layer of " + std::to_string(values.size()) +
                                             " pixels for a region of " + std::to_string(pixels));
    const size_t at = bytes.size();
    bytes.resize(at + pixels * 3 * sizeof(float));
    for (uint64_t i = 0; i < pixels; ++i) std::memcpy(&bytes[at + i * 12], &values[i], 12);
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
  std::vector<std::string> layers;
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
      if (!(v >> name >> type >> count) || type != "f32x3") damaged(key);
      layers.push_back(name);
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
  if (c.region.x1 > (1u << 16) || c.region.y1 > (1u << 16) || pixels * 24 > all.size())
    failRead(path, "its region is larger than its layers (truncated or damaged)");
  if (c.pathsDone < pixels * c.firstSample || c.pathsDone > pixels * c.endSample)
    failRead(path, "its paths-done is outside its samples (damaged)");
  if (layers.size() != 2 || layers[0] != kLayerNames[0] || layers[1] != kLayerNames[1])
    failRead(path, "it holds other layers than radiance.sum and radiance.sumSquares (from a newer wavepath?)");
  size_t at = end + 5;
  for (int layer = 0; layer < 2; ++layer) {
    if (layerSizes[layer] != pixels || all.size() - at < pixels * 12)
      failRead(path, "layer " + layers[layer] + " does not hold one value per pixel of its region (damaged)");
    std::vector<glm::vec4>& values = layerOf(c.accumulation, layer);
    values.assign(pixels, glm::vec4(0.0f));
    for (uint64_t i = 0; i < pixels; ++i) std::memcpy(&values[i], &all[at + i * 12], 12);
    at += pixels * 12;
  }
  if (at != all.size()) failRead(path, "it has bytes after its layers (damaged)");
  return c;
}

}  // namespace wp
