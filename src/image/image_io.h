// Writing rendered radiance as PNG (display-ready sRGB) or EXR (linear float), reading EXR.
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "image/display_settings.h"
#include "image/render_record.h"

namespace wp {

// Linear radiance per pixel, row-major with the top row first. `variance` is the estimated
// variance of each pixel's mean; it is empty, or has as many entries as `mean`.
struct RadianceImage {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec3> mean;
  std::vector<glm::vec3> variance;
  // The feature passes, each a mean over the pixel's samples (docs/production.md): empty,
  // or one entry per pixel. Written to EXR as albedo.R/G/B, normal.X/Y/Z and depth.Z.
  std::vector<glm::vec3> albedo;
  std::vector<glm::vec3> normal;
  std::vector<float> depth;
  // The samples each pixel holds, when they differ between pixels (adaptive sampling); empty
  // when every pixel holds those its record says. Written to EXR as samples.X.
  std::vector<float> sampleCount;
  // What the image holds of which frame (samples, region, scene), when a render made it.
  std::optional<RenderRecord> record;
};

// The exposure that maps the image's log-average luminance to middle grey (Reinhard 2002).
float autoExposure(const RadianceImage& image);

// The display image of `image` as `display` says: one RGBA8 pixel per entry, R in the lowest
// byte (the bytes the PNG holds, and what the viewer shows).
std::vector<uint32_t> displayPixels(const RadianceImage& image, const DisplaySettings& display);

// Writes RGBA8 pixels (R in the lowest byte, alpha dropped) as an 8-bit RGB PNG, atomically
// like writeImage. Throws wp::Error on failure.
void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, const std::vector<uint32_t>& pixels);

// Whether `path` ends in .exr (any case): writeImage writes it as EXR.
bool isExrPath(const std::filesystem::path& path);

// Throws wp::Error unless `path` ends in .png or .exr (any case) and names a file in an
// existing, writable directory; call it before rendering so a typo costs no render time.
void checkOutputPath(const std::filesystem::path& path);

// Writes `image` to `path`, chosen by extension: .png is 8-bit, made for display as `display`
// says (by default clamped to [0, 1] and sRGB-encoded), .exr is 32-bit float linear R, G, B
// plus variance.R/G/B and the feature passes that are present, with image.record in its header (EXR
// only). The file appears whole or not at all
// (written beside it, then renamed). Throws wp::Error on failure.
void writeImage(const std::filesystem::path& path, const RadianceImage& image, const DisplaySettings& display = {});

// The most pixels an image reader accepts: the largest image wavepath renders.
inline constexpr uint64_t kMaxImagePixels = 16384ull * 16384ull;

// Reads R, G, B (and variance.R/G/B, the feature passes and the render record when present) of a scanline EXR
// as float. Throws wp::Error when the file is not a regular file, cannot be read, is
// damaged, lacks R, G or B, or declares more than kMaxImagePixels pixels or more than its
// bytes can hold (checked before the pixels are allocated).
RadianceImage readExr(const std::filesystem::path& path);

}  // namespace wp
