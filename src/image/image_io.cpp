// PNG and EXR output written atomically (PNG through stb_image_write, EXR by exr_writer.h), and
// EXR input through tinyexr.
#include "image/image_io.h"

#include <stb_image_write.h>
#include <tinyexr.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_read.h"
#include "core/log.h"
#include "image/exr_writer.h"
#include "shaders/common/exposure.h"
#include "shaders/common/tone_curves.h"

namespace wp {
namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

fs::path directoryOf(const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); }

[[noreturn]] void failWrite(const fs::path& path, const std::string& reason) {
  throw Error("cannot write image '" + path.string() + "': " + reason);
}

[[noreturn]] void failRead(const fs::path& path, const std::string& reason) {
  throw Error("cannot read EXR '" + path.string() + "': " + reason);
}

void checkImageShape(const fs::path& path, const RadianceImage& image) {
  size_t pixels = size_t(image.width) * image.height;
  auto fits = [pixels](size_t size) { return size == 0 || size == pixels; };
  if (image.width == 0 || image.height == 0 || image.mean.size() != pixels || !fits(image.variance.size()) ||
      !fits(image.albedo.size()) || !fits(image.normal.size()) || !fits(image.depth.size()) ||
      !fits(image.sampleCount.size()))
    failWrite(path, "image is " + std::to_string(image.width) + "x" + std::to_string(image.height) + " but has " +
                        std::to_string(image.mean.size()) + " means and " + std::to_string(image.variance.size()) +
                        " variances, or passes of other sizes (a bug in the caller)");
  if (image.width > uint32_t(std::numeric_limits<int>::max() / 4) ||
      image.height > uint32_t(std::numeric_limits<int>::max()))
    failWrite(path, "image is too large for the PNG and EXR writers; render fewer pixels");
}

std::vector<unsigned char> encodePng(uint32_t width, uint32_t height, const std::vector<uint32_t>& pixels) {
  std::vector<unsigned char> rgb(size_t(width) * height * 3);
  for (size_t i = 0; i < rgb.size() / 3; ++i) {
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = static_cast<unsigned char>(pixels[i] >> (8 * c));
  }
  std::vector<unsigned char> png;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    out->insert(out->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
  };
  int w = int(width), h = int(height);
  if (!stbi_write_png_to_func(append, &png, w, h, 3, rgb.data(), w * 3)) png.clear();
  return png;
}

// Frees what tinyexr allocated in a header and an image, on every exit path.
struct ExrHandles {
  EXRHeader header;
  EXRImage image;
  ExrHandles() {
    InitEXRHeader(&header);
    InitEXRImage(&image);
  }
  ~ExrHandles() {
    FreeEXRImage(&image);
    FreeEXRHeader(&header);
  }
  ExrHandles(const ExrHandles&) = delete;
  ExrHandles& operator=(const ExrHandles&) = delete;
};

std::string takeExrMessage(const char* err) {
  std::string message = err ? err : "unknown tinyexr error";
  if (err) FreeEXRErrorMessage(err);
  while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message;
}

// The channels of `pass` (one vec3 per pixel; none when empty), named layer.<channel name>,
// read in place.
void addChannels(std::vector<ExrChannel>& channels, const std::string& layer, const char* const names[3],
                 const std::vector<glm::vec3>& pass) {
  for (int c = 0; c < 3 && !pass.empty(); ++c) {
    channels.push_back({layer.empty() ? names[c] : layer + "." + names[c], &pass[0][c], 3});
  }
}

const char* const kColourChannels[3] = {"R", "G", "B"};
const char* const kVectorChannels[3] = {"X", "Y", "Z"};

std::vector<unsigned char> encodeExr(const RadianceImage& image) {
  std::vector<ExrChannel> channels;
  addChannels(channels, "", kColourChannels, image.mean);
  addChannels(channels, "variance", kColourChannels, image.variance);
  addChannels(channels, "albedo", kColourChannels, image.albedo);
  addChannels(channels, "normal", kVectorChannels, image.normal);
  if (!image.depth.empty()) channels.push_back({"depth.Z", image.depth.data(), 1});
  if (!image.sampleCount.empty()) channels.push_back({"samples.X", image.sampleCount.data(), 1});
  return encodeZipExr(image.width, image.height, std::move(channels),
                      image.record ? recordAttributes(*image.record) : std::vector<HeaderAttribute>{});
}

// Pixels with a data window beyond kMaxImagePixels, or more than the file could hold at
// any compression tinyexr reads (zlib's best is 1032:1), are refused before tinyexr
// allocates them.
void checkDeclaredPixels(const fs::path& path, const EXRHeader& header, size_t fileBytes) {
  constexpr uint64_t kBestCompression = 2048;
  const int64_t width = int64_t(header.data_window.max_x) - header.data_window.min_x + 1;
  const int64_t height = int64_t(header.data_window.max_y) - header.data_window.min_y + 1;
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width <= 0 || height <= 0 || uint64_t(width) > kMaxImagePixels || uint64_t(height) > kMaxImagePixels ||
      uint64_t(width * height) > kMaxImagePixels) {
    failRead(path, "its data window of " + size + " pixels is empty or more than the " +
                       std::to_string(kMaxImagePixels) + " wavepath reads; use a smaller image");
  }
  uint64_t bytesPerPixel = 0;
  for (int c = 0; c < header.num_channels; ++c) bytesPerPixel += header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF ? 2 : 4;
  if (uint64_t(width * height) * bytesPerPixel > kBestCompression * fileBytes) {
    failRead(path, "it declares " + size + " pixels, more than its " + std::to_string(fileBytes) +
                       " bytes can hold; the file is truncated or damaged");
  }
}

int findChannel(const EXRHeader& header, const char* name) {
  for (int c = 0; c < header.num_channels; ++c)
    if (std::strcmp(header.channels[c].name, name) == 0) return c;
  return -1;
}

}  // namespace

bool isExrPath(const fs::path& path) { return lowerExtension(path) == ".exr"; }

void checkOutputPath(const fs::path& path) {
  std::string ext = lowerExtension(path);
  if (ext != ".png" && ext != ".exr")
    failWrite(path, "unsupported extension '" + path.extension().string() +
                        "'; name the output *.png (8-bit sRGB) or *.exr (linear float)");
  std::error_code ec;
  if (fs::is_directory(path, ec)) failWrite(path, "it is a directory; give a file name ending in .png or .exr");
  fs::path dir = directoryOf(path);
  if (!fs::is_directory(dir, ec))
    failWrite(path, "directory '" + dir.string() + "' does not exist; create it or choose another output path");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    failWrite(path,
              "directory '" + dir.string() + "' is not writable; fix its permissions or choose another path");
}

float autoExposure(const RadianceImage& image) {
  double sum = 0.0;
  for (const glm::vec3& radiance : image.mean) sum += gpu::logLuminance(radiance);
  return gpu::autoExposureScale(float(sum / double(std::max<size_t>(image.mean.size(), 1))));
}

std::vector<uint32_t> displayPixels(const RadianceImage& image, const DisplaySettings& d) {
  std::vector<uint32_t> pixels(image.mean.size());
  for (size_t i = 0; i < pixels.size(); ++i) {
    pixels[i] = gpu::packDisplay(image.mean[i], d.exposure, d.toneMapper, d.transfer, d.gamma);
  }
  return pixels;
}

void writePng(const fs::path& path, uint32_t width, uint32_t height, const std::vector<uint32_t>& pixels) {
  checkOutputPath(path);
  std::vector<unsigned char> bytes = encodePng(width, height, pixels);
  if (bytes.empty()) failWrite(path, "PNG encoding failed (out of memory?); capture a smaller window");
  writeFileAtomically(path, bytes, "image");
}

void writeImage(const fs::path& path, const RadianceImage& image, const DisplaySettings& display) {
  checkOutputPath(path);
  checkImageShape(path, image);
  std::vector<unsigned char> bytes;
  if (isExrPath(path)) {
    bytes = encodeExr(image);
  } else {
    bytes = encodePng(image.width, image.height, displayPixels(image, display));
    if (bytes.empty()) failWrite(path, "PNG encoding failed (out of memory?); render a smaller image");
  }
  writeFileAtomically(path, bytes, "image");
}

RadianceImage readExr(const fs::path& path) {
  // The largest scanline EXR of kMaxImagePixels: six float channels, uncompressed.
  const std::vector<unsigned char> bytes =
      readRegularFile(path, "cannot read EXR '" + path.string() + "'", 24 * kMaxImagePixels + (1u << 20),
                      "an OpenEXR image");
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size()) != TINYEXR_SUCCESS)
    failRead(path, "not an OpenEXR file; check the path");
  if (version.multipart || version.non_image || version.tiled)
    failRead(path,
             "multi-part, deep and tiled EXR files are not supported; save it as a single-part scanline EXR");

  ExrHandles exr;
  const char* err = nullptr;
  if (ParseEXRHeaderFromMemory(&exr.header, &version, bytes.data(), bytes.size(), &err) != TINYEXR_SUCCESS)
    failRead(path, takeExrMessage(err) + "; check that the file is intact");
  checkDeclaredPixels(path, exr.header, bytes.size());
  if (exr.header.compression_type == TINYEXR_COMPRESSIONTYPE_PIZ) {
    // tinyexr 1.0.1's PIZ decoder copies as many bytes as a chunk's header says, past the
    // chunk (found by fuzz_exr): PIZ files are not given to it.
    failRead(path, "it is PIZ-compressed, which wavepath does not read; save it with ZIP compression or none");
  }
  // The channels read: radiance, then the optional variance and feature passes, each read
  // only when all its channels are there.
  const char* names[] = {"R", "G", "B", "variance.R", "variance.G", "variance.B", "albedo.R", "albedo.G",
                         "albedo.B", "normal.X", "normal.Y", "normal.Z", "depth.Z", "samples.X"};
  constexpr int kChannels = int(sizeof(names) / sizeof(names[0]));
  int index[kChannels];
  for (int c = 0; c < kChannels; ++c) index[c] = findChannel(exr.header, names[c]);
  if (index[0] < 0 || index[1] < 0 || index[2] < 0)
    failRead(path, "it has no R, G and B channels; save the radiance as RGB");
  auto hasAll = [&](int first, int count) {
    for (int c = first; c < first + count; ++c)
      if (index[c] < 0) return false;
    return true;
  };
  for (int c = 0; c < exr.header.num_channels; ++c) {
    if (exr.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF)
      exr.header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
  }
  // Any UINT channel is refused, read or not: tinyexr (1.0.1) decodes every channel, and its
  // bound check of a UINT plane is 3 bytes short, so a chunk cut inside one reads past the
  // file (found by fuzz_exr). HALF is read as FLOAT for the same reason: its HALF-to-HALF
  // copy checks nothing.
  for (int c = 0; c < exr.header.num_channels; ++c) {
    if (exr.header.pixel_types[c] == TINYEXR_PIXELTYPE_UINT)
      failRead(path, "channel " + printable(exr.header.channels[c].name, 60) +
                         " holds integers, not floats; save the image without it, or as half or float");
  }
  // tinyexr (1.0.1) sets the image's channel count only once decoding succeeds, but on a
  // failure frees the image by it (DecodeEXRImage: FreeEXRImage): set beforehand, every plane
  // is freed, not only the array of them.
  exr.image.num_channels = exr.header.num_channels;
  if (LoadEXRImageFromMemory(&exr.image, &exr.header, bytes.data(), bytes.size(), &err) != TINYEXR_SUCCESS) {
    // Freed but still pointed at: forget the pointers, or ~ExrHandles would free them again.
    InitEXRImage(&exr.image);
    failRead(path, takeExrMessage(err) + "; check that the file is intact");
  }

  std::vector<HeaderAttribute> attributes;
  for (int a = 0; a < exr.header.num_custom_attributes; ++a) {
    const EXRAttribute& attribute = exr.header.custom_attributes[a];
    std::vector<unsigned char> value;
    if (attribute.value != nullptr && attribute.size > 0) value.assign(attribute.value, attribute.value + attribute.size);
    attributes.push_back({attribute.name, attribute.type, std::move(value)});
  }
  RadianceImage result;
  result.record = recordFromAttributes(attributes, path.string());
  result.width = uint32_t(exr.image.width);
  result.height = uint32_t(exr.image.height);
  size_t pixels = size_t(result.width) * result.height;
  auto channel = [&](int c) { return reinterpret_cast<const float*>(exr.image.images[index[c]]); };
  auto readVectors = [&](int first, std::vector<glm::vec3>& to) {
    if (!hasAll(first, 3)) return;
    to.resize(pixels);
    for (size_t i = 0; i < pixels; ++i) to[i] = glm::vec3(channel(first)[i], channel(first + 1)[i], channel(first + 2)[i]);
  };
  readVectors(0, result.mean);
  readVectors(3, result.variance);
  readVectors(6, result.albedo);
  readVectors(9, result.normal);
  if (hasAll(12, 1)) result.depth.assign(channel(12), channel(12) + pixels);
  if (hasAll(13, 1)) result.sampleCount.assign(channel(13), channel(13) + pixels);
  return result;
}

}  // namespace wp
