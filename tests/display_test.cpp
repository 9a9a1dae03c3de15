// The PNG is the EXR's linear radiance through the chosen exposure, tone curve and transfer
// function, byte for byte (the curves' values are tested in camera_test).
#include <gtest/gtest.h>

#include <fstream>

#include <stb_image.h>

#include "image/image_io.h"
#include "shaders/common/exposure.h"
#include "shaders/common/tone_curves.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

// A plane of albedo 0.25 and a sphere of albedo 0.6 under the white sky, radiance 0.25, 0.6
// and 1: enough distinct values for every curve to matter.
const char* kScene = R"({
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
  "nodes": [
    {"extras": {"wavepath": {"shape": "plane", "material": 0}}},
    {"translation": [0, 2, 0], "extras": {"wavepath": {"shape": "sphere", "radius": 1.0, "material": 1}}},
    {"camera": 0, "translation": [0, 3, 6], "rotation": [-0.2588190, 0, 0, 0.9659258]}
  ],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.01}}],
  "materials": [
    {"pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.25, 0.25, 1]}},
    {"pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1]}}
  ]
})";

struct DisplayCase {
  std::vector<std::string> flags;
  uint32_t mapper;
  uint32_t transfer;
  float gamma;
  float exposure;  // < 0: automatic, from the image
};

class Display : public ::testing::Test {
protected:
  std::filesystem::path dir = scratchDirectory("display");

  std::filesystem::path render(const std::string& name, const std::vector<std::string>& flags) {
    std::filesystem::path out = dir / name;
    std::vector<std::string> args = {"render", (dir / "scene.gltf").string(), "-o", out.string(), "--width", "32",
                                     "--height", "24", "--spp", "4", "--seed", "3"};
    args.insert(args.end(), flags.begin(), flags.end());
    RunResult r = runWavepath(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return out;
  }
};

TEST_F(Display, PngIsTheRadianceThroughExposureToneCurveAndTransfer) {
  std::ofstream(dir / "scene.gltf") << kScene;
  RadianceImage radiance = readExr(render("linear.exr", {}));
  const std::vector<DisplayCase> cases = {
      {{}, WP_TONE_CLAMP, WP_TRANSFER_SRGB, 2.2f, 1.0f},
      {{"--tonemap", "reinhard"}, WP_TONE_REINHARD, WP_TRANSFER_SRGB, 2.2f, 1.0f},
      {{"--tonemap", "filmic", "--ev100", "-1"}, WP_TONE_HABLE, WP_TRANSFER_SRGB, 2.2f,
       gpu::exposureScale(gpu::maxLuminanceFromEv100(-1.0f))},
      {{"--tonemap", "aces", "--shutter", "0.02", "--iso", "200"}, WP_TONE_ACES, WP_TRANSFER_SRGB, 2.2f,
       gpu::exposureScale(gpu::maxLuminanceFromSettings(16.0f, 0.02f, 200.0f))},
      {{"--gamma", "1.8"}, WP_TONE_CLAMP, WP_TRANSFER_GAMMA, 1.8f, 1.0f},
      {{"--auto-exposure", "--tonemap", "reinhard"}, WP_TONE_REINHARD, WP_TRANSFER_SRGB, 2.2f, -1.0f},
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    const DisplayCase& c = cases[k];
    SCOPED_TRACE("case " + std::to_string(k));
    std::filesystem::path png = render("display" + std::to_string(k) + ".png", c.flags);
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load(png.c_str(), &w, &h, &channels, 3);
    ASSERT_NE(pixels, nullptr);
    ASSERT_EQ(size_t(w) * size_t(h), radiance.mean.size());
    float exposure = c.exposure < 0.0f ? autoExposure(radiance) : c.exposure;
    size_t mismatches = 0;
    for (size_t i = 0; i < radiance.mean.size(); ++i) {
      uint32_t expected = gpu::packDisplay(radiance.mean[i], exposure, c.mapper, c.transfer, c.gamma);
      for (int channel = 0; channel < 3; ++channel) {
        mismatches += pixels[3 * i + channel] != ((expected >> (8 * channel)) & 0xffu);
      }
    }
    stbi_image_free(pixels);
    EXPECT_EQ(mismatches, 0u);
  }
}

}  // namespace
}  // namespace wp::test
