// The sky end to end: a furnace under a constant sky, and the three light-sampling modes
// agreeing under a map with a bright spot.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "image/image_io.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

// A Lambertian sphere of albedo `albedo` seen from outside, and nothing else.
std::string sphereScene(float albedo) {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"extras": {"wavepath": {"shape": "sphere", "radius": 1.0, "material": 0}}},
              {"camera": 0, "translation": [0, 0.5, 4]}],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "znear": 0.01}}],
    "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [)" +
         std::to_string(albedo) + "," + std::to_string(albedo) + "," + std::to_string(albedo) +
         R"(, 1]}, "extras": {"wavepath": {"bsdf": "lambert"}}}]})";
}

struct Mean {
  double value = 0.0;
  double standardError = 0.0;
};

// Image mean of the red channel and its standard error (pixels are independent).
Mean imageMean(const RadianceImage& image) {
  Mean m;
  double variance = 0.0;
  for (size_t i = 0; i < image.mean.size(); ++i) {
    m.value += image.mean[i].x;
    variance += image.variance[i].x;
  }
  double n = double(image.mean.size());
  m.value /= n;
  m.standardError = std::sqrt(variance) / n;
  return m;
}

RadianceImage render(const std::filesystem::path& scene, std::vector<std::string> flags) {
  std::filesystem::path out = scene.parent_path() / "out.exr";
  std::vector<std::string> args = {"render", scene.string(), "-o", out.string(), "--width", "32", "--height", "32"};
  args.insert(args.end(), flags.begin(), flags.end());
  RunResult r = runWavepath(args);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return readExr(out);
}

// A Lambertian sphere of albedo 1 under a constant sky of radiance L reflects L: every pixel,
// sphere or sky, is L.
TEST(Sky, FurnaceUnderAConstantSkyRendersTheSkyRadianceEverywhere) {
  std::filesystem::path dir = scratchDirectory("sky-furnace");
  std::ofstream(dir / "scene.gltf") << sphereScene(1.0f);
  const double radiance = 2.5;
  for (const char* mode : {"mis", "nee", "bsdf"}) {
    SCOPED_TRACE(mode);
    RadianceImage image = render(dir / "scene.gltf", {"--spp", "256", "--mode", mode, "--sky-intensity", "2.5"});
    Mean m = imageMean(image);
    EXPECT_LT(m.standardError, 0.0025 * radiance);
    EXPECT_NEAR(m.value, radiance, 0.01 * radiance);
  }
}

// MIS, NEE only and BSDF only estimate the same image under a sky map: their means agree
// within z < 4 (as in render_test). The map is a smooth gradient with a small spot 50x
// brighter, so that sampling by luminance matters but BSDF sampling still converges.
TEST(Sky, MisNeeAndBsdfSamplingAgreeUnderAMap) {
  std::filesystem::path dir = scratchDirectory("sky-map");
  RadianceImage map;
  map.width = 64;
  map.height = 32;
  for (uint32_t y = 0; y < map.height; ++y) {
    for (uint32_t x = 0; x < map.width; ++x) {
      float sky = 0.2f + 0.8f * float(map.height - y) / float(map.height);
      bool spot = x >= 40 && x < 43 && y >= 8 && y < 11;
      map.mean.push_back(glm::vec3(sky * (spot ? 50.0f : 1.0f), sky, sky * 0.7f));
    }
  }
  writeImage(dir / "sky.exr", map);
  std::ofstream(dir / "scene.gltf") << sphereScene(0.7f);
  std::vector<Mean> means;
  for (const char* mode : {"mis", "nee", "bsdf"}) {
    means.push_back(
        imageMean(render(dir / "scene.gltf", {"--spp", "256", "--mode", mode, "--sky", (dir / "sky.exr").string()})));
  }
  for (size_t a = 0; a < means.size(); ++a) {
    for (size_t b = a + 1; b < means.size(); ++b) {
      double se = std::hypot(means[a].standardError, means[b].standardError);
      EXPECT_LT(std::abs(means[a].value - means[b].value) / se, 4.0) << means[a].value << " vs " << means[b].value;
      EXPECT_LT(se, 0.02 * means[a].value);
    }
  }
}

}  // namespace
}  // namespace wp::test
