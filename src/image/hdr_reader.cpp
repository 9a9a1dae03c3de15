// Radiance RGBE decoding with every count checked against the bytes there are. stb_image's
// decoder loops forever on a run length of 0 (and so on every truncated file) and allocates
// what the header declares before reading a pixel, so wavepath reads .hdr itself.
#include "image/hdr_reader.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/file_read.h"

namespace wp {
namespace {

// Widths for which writers run-length encode scanlines (Radiance's and stb's rule).
constexpr uint32_t kMinRleWidth = 8;
constexpr uint32_t kMaxRleWidth = 0x7fff;
// The longest run or literal a count byte can say.
constexpr uint32_t kMaxRun = 127;

class HdrDecoder {
public:
  HdrDecoder(const std::vector<unsigned char>& bytes, const std::filesystem::path& path) : bytes_(bytes), path_(path) {}

  RadianceImage decode() {
    readHeader();
    checkDeclaredSize();
    RadianceImage image;
    image.width = width_;
    image.height = height_;
    image.mean.resize(size_t(width_) * height_);
    std::vector<unsigned char> rgbe(size_t(width_) * 4);
    for (uint32_t y = 0; y < height_; ++y) {
      readScanline(rgbe, y);
      for (uint32_t x = 0; x < width_; ++x) image.mean[size_t(y) * width_ + x] = toRadiance(&rgbe[4 * x]);
    }
    return image;
  }

private:
  [[noreturn]] void fail(const std::string& message) const {
    throw Error("cannot read HDR '" + path_.string() + "': " + message);
  }

  // The next header line without its newline; fails at the end of the file.
  std::string_view line() {
    const size_t start = at_;
    while (at_ < bytes_.size() && bytes_[at_] != '\n') ++at_;
    if (at_ == bytes_.size()) fail("its header ends before the pixels; the file is truncated or not an HDR image");
    return {reinterpret_cast<const char*>(bytes_.data()) + start, at_++ - start};
  }

  void readHeader() {
    const std::string_view magic = bytes_.size() >= 2 ? line() : std::string_view();
    if (magic.substr(0, 2) != "#?") fail("not a Radiance HDR file; save the sky as .hdr or .exr");
    bool rgbe = false;
    for (std::string_view l = line(); !l.empty(); l = line()) {
      if (l.substr(0, 7) == "FORMAT=") {
        if (l != "FORMAT=32-bit_rle_rgbe") {
          fail("its format is '" + std::string(l.substr(7, 40)) + "', not 32-bit_rle_rgbe; save it with RGB primaries");
        }
        rgbe = true;
      }
    }
    if (!rgbe) fail("its header has no FORMAT=32-bit_rle_rgbe line; re-export the image");
    const std::string resolution(line());
    unsigned long height = 0, width = 0;
    int consumed = 0;
    if (std::sscanf(resolution.c_str(), "-Y %lu +X %lu%n", &height, &width, &consumed) != 2 ||
        size_t(consumed) != resolution.size()) {
      fail("its resolution line is '" + resolution.substr(0, 40) +
           "'; only '-Y height +X width' (rows from the top) is supported");
    }
    if (width == 0 || height == 0 || width > kMaxImagePixels || height > kMaxImagePixels ||
        width * height > kMaxImagePixels) {
      fail(std::to_string(width) + "x" + std::to_string(height) + " pixels is empty or more than the " +
           std::to_string(kMaxImagePixels) + " wavepath reads; use a smaller image");
    }
    width_ = uint32_t(width);
    height_ = uint32_t(height);
  }

  bool runLengthEncodable() const { return width_ >= kMinRleWidth && width_ <= kMaxRleWidth; }

  // The fewest bytes the pixels can take: 4 a pixel flat, or per run-length scanline its
  // 4-byte start and, for each of 4 components, two bytes per run of at most 127.
  void checkDeclaredSize() const {
    uint64_t row = 4ull * width_;
    if (runLengthEncodable()) row = std::min<uint64_t>(row, 4 + 4 * 2 * ((width_ + kMaxRun - 1) / kMaxRun));
    const uint64_t available = bytes_.size() - at_;
    if (row * height_ > available) {
      fail("its header declares " + std::to_string(width_) + "x" + std::to_string(height_) + " pixels, more than its " +
           std::to_string(available) + " bytes of pixel data can hold; the file is truncated or damaged");
    }
  }

  unsigned char next(uint32_t y) {
    if (at_ >= bytes_.size()) fail("row " + std::to_string(y) + " ends past the end of the file; the file is truncated");
    return bytes_[at_++];
  }

  void readScanline(std::vector<unsigned char>& rgbe, uint32_t y) {
    const bool encoded = runLengthEncodable() && at_ + 4 <= bytes_.size() && bytes_[at_] == 2 &&
                         bytes_[at_ + 1] == 2 && !(bytes_[at_ + 2] & 0x80);
    if (!encoded) {
      for (unsigned char& byte : rgbe) byte = next(y);
      return;
    }
    const uint32_t length = uint32_t(bytes_[at_ + 2]) << 8 | bytes_[at_ + 3];
    at_ += 4;
    if (length != width_) {
      fail("row " + std::to_string(y) + " says it is " + std::to_string(length) + " pixels wide, not " +
           std::to_string(width_) + "; the file is damaged");
    }
    for (uint32_t component = 0; component < 4; ++component) {
      for (uint32_t x = 0; x < width_;) {
        uint32_t count = next(y);
        const bool run = count > 128;
        if (run) count -= 128;
        if (count == 0 || count > width_ - x) {
          fail("row " + std::to_string(y) + " has a run of " + std::to_string(count) + " pixels where " +
               std::to_string(width_ - x) + " are left; the file is damaged");
        }
        const unsigned char value = run ? next(y) : 0;
        for (uint32_t i = 0; i < count; ++i, ++x) rgbe[4 * x + component] = run ? value : next(y);
      }
    }
  }

  static glm::vec3 toRadiance(const unsigned char* rgbe) {
    if (rgbe[3] == 0) return glm::vec3(0.0f);
    const float scale = std::ldexp(1.0f, int(rgbe[3]) - (128 + 8));
    return glm::vec3(rgbe[0], rgbe[1], rgbe[2]) * scale;
  }

  const std::vector<unsigned char>& bytes_;
  const std::filesystem::path& path_;
  size_t at_ = 0;
  uint32_t width_ = 0, height_ = 0;
};

}  // namespace

RadianceImage readHdr(const std::filesystem::path& path) {
  // 4 bytes a pixel at most (flat scanlines), and a header.
  const std::vector<unsigned char> bytes = readRegularFile(path, "cannot read HDR '" + path.string() + "'",
                                                           4 * kMaxImagePixels + (1u << 20), "a Radiance .hdr image");
  return HdrDecoder(bytes, path).decode();
}

}  // namespace wp
