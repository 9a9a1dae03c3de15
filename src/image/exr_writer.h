// OpenEXR scanline files with ZIP compression, the blocks of 16 scanlines compressed on all
// cores: tinyexr compressed them one after another, and a 4K image with its feature passes
// took longer to write than to render at a few samples.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>
#include <vector>

#include "image/render_record.h"

namespace wp {

// The bytes of `values` as OpenEXR stores numbers (little-endian): a header attribute's value.
template <typename T>
std::vector<unsigned char> exrBytes(std::initializer_list<T> values) {
  static_assert(std::endian::native == std::endian::little, "EXR numbers are stored as this machine's");
  std::vector<unsigned char> bytes(values.size() * sizeof(T));
  if (!bytes.empty()) std::memcpy(bytes.data(), values.begin(), bytes.size());
  return bytes;
}

// One channel of 32-bit floats, read where it lies: pixel i (row-major) at values[i * stride]
// (a component of an image's vec3 pass: its first float's component, stride 3).
struct ExrChannel {
  std::string name;
  const float* values = nullptr;
  size_t stride = 1;
};

// The bytes of a single-part scanline EXR of `channels` (sorted here by name, as OpenEXR
// requires), ZIP-compressed, with `attributes` added to the header after the required ones.
// Requires every channel to hold width * height values, width and height at least 1, and
// names and types without NUL bytes.
std::vector<unsigned char> encodeZipExr(uint32_t width, uint32_t height, std::vector<ExrChannel> channels,
                                        const std::vector<HeaderAttribute>& attributes);

}  // namespace wp
