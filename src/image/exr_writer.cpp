// The OpenEXR 2 file layout (openexr.com, "OpenEXR File Layout"): magic and version, header
// attributes, the table of chunk offsets, then the chunks, each a block of 16 scanlines whose
// channels are stored one after another per scanline, reordered and delta-coded, then
// deflated.
#include "image/exr_writer.h"

#include <libdeflate.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <initializer_list>
#include <new>
#include <string>

#include "core/parallel.h"

namespace wp {
namespace {

constexpr uint32_t kScanlinesPerZipBlock = 16;
constexpr unsigned char kZipCompression = 3;  // OpenEXR's ZIP_COMPRESSION
constexpr int32_t kFloatPixels = 2;            // OpenEXR's FLOAT pixel type
// libdeflate's default level, whose files are the size of zlib's default (which tinyexr and
// OpenEXR 2 use) in about half its time (docs/performance.md). zlib's levels 4 and 1 had written
// the instanced scene's EXR (960x540 with its passes) 0.4% and 1.2% larger for 2% and 15% less
// time.
constexpr int kDeflateLevel = 6;
// Names up to this length fit a version-2 file without its long-names flag.
constexpr size_t kShortNameLength = 31;

// Numbers are written as this machine stores them, which is OpenEXR's byte order.
static_assert(std::endian::native == std::endian::little, "the EXR writer needs a little-endian machine");

void putBytes(std::vector<unsigned char>& out, const void* data, size_t size) {
  const unsigned char* bytes = static_cast<const unsigned char*>(data);
  out.insert(out.end(), bytes, bytes + size);
}

template <typename T>
void put(std::vector<unsigned char>& out, T value) {
  putBytes(out, &value, sizeof(value));
}

void putString(std::vector<unsigned char>& out, const std::string& text) {
  putBytes(out, text.c_str(), text.size() + 1);
}

void putAttribute(std::vector<unsigned char>& out, const std::string& name, const std::string& type,
                  const std::vector<unsigned char>& value) {
  putString(out, name);
  putString(out, type);
  put<int32_t>(out, int32_t(value.size()));
  putBytes(out, value.data(), value.size());
}

std::vector<unsigned char> channelList(const std::vector<ExrChannel>& channels) {
  std::vector<unsigned char> list;
  for (const ExrChannel& c : channels) {
    putString(list, c.name);
    put<int32_t>(list, kFloatPixels);
    put<uint32_t>(list, 0);  // pLinear and three reserved bytes
    put<int32_t>(list, 1);   // x sampling
    put<int32_t>(list, 1);   // y sampling
  }
  list.push_back(0);
  return list;
}

std::vector<unsigned char> box(uint32_t width, uint32_t height) {
  return exrBytes<int32_t>({0, 0, int32_t(width) - 1, int32_t(height) - 1});
}

// A libdeflate compressor, freed with its owner.
struct Compressor {
  libdeflate_compressor* state = libdeflate_alloc_compressor(kDeflateLevel);
  Compressor() {
    if (!state) throw std::bad_alloc();  // said as "out of host memory" (main.cpp)
  }
  ~Compressor() { libdeflate_free_compressor(state); }
  Compressor(const Compressor&) = delete;
  Compressor& operator=(const Compressor&) = delete;
};

// The chunk of the block of scanlines [y0, y1): its first scanline, its size and its data,
// deflated unless that would not make it smaller (a reader tells the two apart by size).
std::vector<unsigned char> zipBlock(uint32_t width, uint32_t y0, uint32_t y1, const std::vector<ExrChannel>& channels) {
  std::vector<float> values;
  values.reserve(size_t(y1 - y0) * width * channels.size());
  for (uint32_t y = y0; y < y1; ++y) {
    for (const ExrChannel& c : channels) {
      const float* row = c.values + size_t(y) * width * c.stride;
      for (uint32_t x = 0; x < width; ++x) values.push_back(row[x * c.stride]);
    }
  }
  const unsigned char* raw = reinterpret_cast<const unsigned char*>(values.data());
  const size_t rawSize = values.size() * sizeof(float);  // even
  // The bytes of even offsets, then those of odd offsets: the high and low bytes of the floats
  // then sit in long runs of similar values...
  std::vector<unsigned char> coded(rawSize);
  for (size_t i = 0; i < rawSize / 2; ++i) {
    coded[i] = raw[2 * i];
    coded[rawSize / 2 + i] = raw[2 * i + 1];
  }
  // ...which differences from the previous byte (plus 128, modulo 256) make small.
  for (size_t i = rawSize - 1; i > 0; --i) coded[i] = static_cast<unsigned char>(coded[i] - coded[i - 1] + 128);

  // The chunk's two numbers, then its data: deflated into room one byte short of the raw
  // block, where libdeflate returns 0 for a block that does not fit, which is then stored.
  constexpr size_t kChunkHeader = 2 * sizeof(int32_t);
  std::vector<unsigned char> chunk(kChunkHeader + rawSize);
  Compressor compressor;
  size_t dataSize = libdeflate_zlib_compress(compressor.state, coded.data(), rawSize, chunk.data() + kChunkHeader,
                                             rawSize - 1);
  if (dataSize == 0) {
    std::copy(raw, raw + rawSize, chunk.data() + kChunkHeader);
    dataSize = rawSize;
  }
  chunk.resize(kChunkHeader + dataSize);
  const int32_t numbers[2] = {int32_t(y0), int32_t(dataSize)};
  std::memcpy(chunk.data(), numbers, kChunkHeader);
  return chunk;
}

// Every block's chunk, compressed on every core.
std::vector<std::vector<unsigned char>> zipBlocks(uint32_t width, uint32_t height,
                                                  const std::vector<ExrChannel>& channels) {
  const uint32_t count = (height + kScanlinesPerZipBlock - 1) / kScanlinesPerZipBlock;
  std::vector<std::vector<unsigned char>> chunks(count);
  forEachInParallel(count, [&](uint32_t b) {
    const uint32_t y0 = b * kScanlinesPerZipBlock;
    chunks[b] = zipBlock(width, y0, std::min(height, y0 + kScanlinesPerZipBlock), channels);
  });
  return chunks;
}

}  // namespace

std::vector<unsigned char> encodeZipExr(uint32_t width, uint32_t height, std::vector<ExrChannel> channels,
                                        const std::vector<HeaderAttribute>& attributes) {
  std::sort(channels.begin(), channels.end(), [](const ExrChannel& a, const ExrChannel& b) { return a.name < b.name; });
  bool longNames = false;
  for (const ExrChannel& c : channels) longNames = longNames || c.name.size() > kShortNameLength;
  for (const HeaderAttribute& a : attributes) {
    longNames = longNames || a.name.size() > kShortNameLength || a.type.size() > kShortNameLength;
  }

  std::vector<unsigned char> out = {0x76, 0x2f, 0x31, 0x01};       // magic number
  // Version 2, one part of scanlines; the 0x04 of the second byte (bit 10) allows names
  // longer than 31 bytes.
  out.insert(out.end(), {2, static_cast<unsigned char>(longNames ? 0x04 : 0x00), 0, 0});
  putAttribute(out, "channels", "chlist", channelList(channels));
  putAttribute(out, "compression", "compression", {kZipCompression});
  putAttribute(out, "dataWindow", "box2i", box(width, height));
  putAttribute(out, "displayWindow", "box2i", box(width, height));
  putAttribute(out, "lineOrder", "lineOrder", {0});  // increasing y
  putAttribute(out, "pixelAspectRatio", "float", exrBytes<float>({1.0f}));
  putAttribute(out, "screenWindowCenter", "v2f", exrBytes<float>({0.0f, 0.0f}));
  putAttribute(out, "screenWindowWidth", "float", exrBytes<float>({1.0f}));
  for (const HeaderAttribute& a : attributes) putAttribute(out, a.name, a.type, a.value);
  out.push_back(0);  // end of the header

  const std::vector<std::vector<unsigned char>> chunks = zipBlocks(width, height, channels);
  uint64_t offset = out.size() + chunks.size() * sizeof(uint64_t);
  for (const std::vector<unsigned char>& c : chunks) {
    put<uint64_t>(out, offset);
    offset += c.size();
  }
  out.reserve(offset);
  for (const std::vector<unsigned char>& c : chunks) putBytes(out, c.data(), c.size());
  return out;
}

}  // namespace wp
