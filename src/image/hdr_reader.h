// Reading Radiance RGBE (.hdr) images, safely on any bytes.
#pragma once

#include <filesystem>

#include "image/image_io.h"

namespace wp {

// Reads a Radiance .hdr file: the "#?" header with FORMAT=32-bit_rle_rgbe, the "-Y H +X W"
// orientation (top row first), scanlines flat or run-length encoded, decoded as stb_image
// does (value * 2^(exponent - 136)). Throws wp::Error, one line naming the file, for any other
// file, a damaged or truncated one, or one declaring more pixels than its bytes can hold or
// than kMaxImagePixels (checked before anything is allocated). Never reads past the file.
RadianceImage readHdr(const std::filesystem::path& path);

}  // namespace wp
