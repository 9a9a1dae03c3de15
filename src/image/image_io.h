// Writing rendered radiance as PNG (display-ready sRGB) or EXR (linear float), reading EXR.
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <vector>

namespace wp {

// Linear radiance per pixel, row-major with the top row first. `variance` is the estimated
// variance of each pixel's mean; it is empty, or has as many entries as `mean`.
struct RadianceImage {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec3> mean;
  std::vector<glm::vec3> variance;
};

// Throws wp::Error unless `path` ends in .png or .exr (any case) and names a file in an
// existing, writable directory; call it before rendering so a typo costs no render time.
void checkOutputPath(const std::filesystem::path& path);

// Writes `image` to `path`, chosen by extension: .png is 8-bit sRGB (clamped to [0, 1]),
// .exr is 32-bit float linear R, G, B plus variance.R/G/B when variance is present. The file
// appears whole or not at all (written beside it, then renamed). Throws wp::Error on failure.
void writeImage(const std::filesystem::path& path, const RadianceImage& image);

// Reads R, G, B (and variance.R/G/B when present) of a scanline or tiled EXR as float.
// Throws wp::Error when the file cannot be read or lacks R, G or B.
RadianceImage readExr(const std::filesystem::path& path);

}  // namespace wp
