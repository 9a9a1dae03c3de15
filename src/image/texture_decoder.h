// Decoding PNG, JPEG and WebP textures with libpng, libjpeg-turbo and libwebp, safely on any bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace wp {

// RGBA8 pixels, top row first, r in the first byte.
struct Rgba8Image {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

enum class ImageFormat { Png, Jpeg, Webp, Ktx2, Unknown };

// The format of an image file, by its signature (glTF's mimeType is not trusted).
ImageFormat imageFormatOf(const uint8_t* bytes, size_t size);

// Decodes a PNG, JPEG or WebP (told apart by their signatures) into RGBA8 as stb_image did
// before: grey, palette and transparency expanded, 16-bit channels cut to their high byte, no
// gamma applied. libpng and libjpeg-turbo rather than stb_image, which overflows its Huffman
// tables on hostile JPEGs and is not meant for untrusted files. Throws wp::Error with the
// reason for another format (KTX2 named as such), a damaged or truncated file (libjpeg's
// corrupt-data warnings included), more than kMaxImagePixels pixels or more than the bytes
// could hold (checked before the pixels are allocated), or a JPEG of more scans than any
// encoder writes.
Rgba8Image decodeTexture(const uint8_t* bytes, size_t size);

}  // namespace wp
