// Loading equirectangular skies (.hdr through stb_image, .exr through tinyexr) and building
// their sin(theta)-weighted luminance distribution.
#include "scene/environment_map.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "image/hdr_reader.h"
#include "image/image_io.h"
#include "scene/scene_limits.h"
#include "shaders/common/sampling.h"

namespace wp {
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void skyError(const fs::path& path, const std::string& message) {
  throw Error("sky '" + path.string() + "': " + message);
}

// Turns running sums (in double, so thousands of tiny terms are not lost) into a float CDF
// that starts at 0 and ends at exactly 1, as the GPU's binary search requires; all zeros
// become uniform. Float rounding keeps it non-decreasing.
void appendCdf(const std::vector<double>& weights, std::vector<float>& cdf) {
  double total = 0.0;
  for (double w : weights) total += w;
  size_t n = weights.size();
  double sum = 0.0;
  cdf.push_back(0.0f);
  for (size_t i = 0; i < n; ++i) {
    sum += total > 0.0 ? weights[i] : 1.0;
    cdf.push_back(i + 1 == n ? 1.0f : static_cast<float>(sum / (total > 0.0 ? total : double(n))));
  }
}

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace

EnvironmentMap makeEnvironmentMap(uint32_t width, uint32_t height, const std::vector<glm::vec3>& radiance) {
  EnvironmentMap map;
  map.width = width;
  map.height = height;
  map.radiance.reserve(radiance.size());
  for (size_t i = 0; i < radiance.size(); ++i) {
    glm::vec3 c = radiance[i];
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
      throw Error("texel (" + std::to_string(i % width) + ", " + std::to_string(i / width) +
                  ") is not a finite number; fix or re-export the image");
    if (std::max({c.x, c.y, c.z}) > kMaxRadiance) {
      char text[120];
      std::snprintf(text, sizeof(text), "texel (%zu, %zu) is %g, above %g, brighter than any real sky", i % width,
                    i / width, double(std::max({c.x, c.y, c.z})), kMaxRadiance);
      throw Error(std::string(text) + "; fix or re-export the image");
    }
    map.radiance.emplace_back(glm::max(c, glm::vec3(0.0f)), 0.0f);
  }

  std::vector<double> luminance(map.radiance.size());
  for (size_t i = 0; i < luminance.size(); ++i) luminance[i] = gpu::luminance(glm::vec3(map.radiance[i]));
  // A black sky sends nothing and is never chosen by power, but its sampler stays defined:
  // constant weights make it (nearly) uniform over the sphere.
  bool black = std::all_of(luminance.begin(), luminance.end(), [](double l) { return l == 0.0; });

  // Texel (x, y) covers theta in [y, y + 1] * pi / height and 2 pi / width of phi. Its
  // weight is luminance * sin(theta at its centre), proportional to the power it sends
  // (pbrt-v3 §14.2.4); its exact solid angle is used for the integral.
  std::vector<double> rowWeights(height), columnWeights(width);
  double dPhi = 2.0 * kPi / width;
  for (uint32_t y = 0; y < height; ++y) {
    double theta0 = kPi * y / height, theta1 = kPi * (y + 1) / height;
    double sinTheta = std::sin(kPi * (y + 0.5) / height);
    double solidAngle = dPhi * (std::cos(theta0) - std::cos(theta1));
    double rowSum = 0.0;
    for (uint32_t x = 0; x < width; ++x) {
      double l = luminance[size_t(y) * width + x];
      columnWeights[x] = (black ? 1.0 : l) * sinTheta;
      rowSum += columnWeights[x];
      map.luminanceIntegral += l * solidAngle;
    }
    rowWeights[y] = rowSum;
    appendCdf(columnWeights, map.conditionalCdf);
  }
  appendCdf(rowWeights, map.marginalCdf);
  return map;
}

EnvironmentMap loadEnvironmentMap(const fs::path& path) {
  std::string ext = lowerExtension(path);
  RadianceImage image;
  if (ext == ".hdr") {
    image = readHdr(path);
  } else if (ext == ".exr") {
    image = readExr(path);
  } else {
    skyError(path, "unsupported format '" + ext + "'; give an equirectangular .hdr or .exr image");
  }
  try {
    return makeEnvironmentMap(image.width, image.height, image.mean);
  } catch (const Error& e) {
    skyError(path, e.what());
  }
}

void checkSkyIntensity(const EnvironmentMap& map, double intensity) {
  float brightest = 0.0f;
  for (const glm::vec4& texel : map.radiance) brightest = std::max({brightest, texel.x, texel.y, texel.z});
  if (double(brightest) * intensity > kMaxRadiance) {
    char text[200];
    std::snprintf(text, sizeof(text),
                  "--sky-intensity %g makes the sky's brightest texel %g, above %g, brighter than any real sky; "
                  "lower --sky-intensity",
                  intensity, double(brightest) * intensity, kMaxRadiance);
    throw Error(text);
  }
}

double environmentPower(const EnvironmentMap& map, double intensity, double sceneRadius) {
  return kPi * sceneRadius * sceneRadius * intensity * map.luminanceIntegral;
}

}  // namespace wp
