// Adaptive sampling end to end on both backends (lavapipe under validation, PoCL): in a
// scene of flat sky and a noisy floor, the sky stops at the minimum, the floor goes on, every
// pixel that stopped early met the threshold when it stopped, the image agrees with the
// render of every sample, and it does not depend on how the samples are cut into passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "image/image_io.h"
#include "support/gltf_writer.h"
#include "support/render_exr.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

constexpr uint32_t kSpp = 256, kMinSamples = 16, kInterval = 8;
constexpr float kThreshold = 0.03f;

// The camera looks down -z and a little down at a floor at y = -1 under a uniform sky, with a
// small square hovering above it: the sky fills the top of the image with one radiance (no
// variance at all), the floor is lit by the sky through MIS and shadowed in part (noisy).
std::filesystem::path adaptiveScene() {
  TestScene s;
  s.materials.push_back({glm::vec3(0.7f)});
  TestMesh floor;
  floor.positions = {{-20, -1, 20}, {20, -1, 20}, {20, -1, -20}, {-20, -1, -20}};
  floor.indices = {0, 1, 2, 0, 2, 3};
  TestMesh occluder;
  occluder.positions = {{-0.5f, -0.4f, -3.5f}, {0.5f, -0.4f, -3.5f}, {0.5f, -0.4f, -4.5f}, {-0.5f, -0.4f, -4.5f}};
  occluder.indices = {0, 2, 1, 0, 3, 2};
  s.meshes = {floor, occluder};
  return writeGltf(s, scratchDirectory("adaptive") / "adaptive.gltf");
}

class Adaptive : public ::testing::TestWithParam<std::string> {
protected:
  RadianceImage render(std::vector<std::string> extra) {
    std::vector<std::string> flags = {"--width", "24", "--height", "24", "--spp", std::to_string(kSpp),
                                      "--sky-color", "0.5,0.5,0.5"};
    flags.insert(flags.end(), extra.begin(), extra.end());
    return renderExr(GetParam(), scene, flags);
  }
  std::vector<std::string> adaptiveFlags() {
    return {"--adaptive", "0.03", "--adaptive-min-samples", std::to_string(kMinSamples)};
  }
  std::filesystem::path scene = adaptiveScene();
};

// The relative error adaptive sampling estimates (accumulation.h), from the EXR: the root of
// the channels' mean variance of the mean over their mean radiance, the dark floor below.
double relativeError(const RadianceImage& image, size_t i) {
  const glm::dvec3 variance(image.variance[i]), mean(image.mean[i]);
  const double standardError = std::sqrt((variance.x + variance.y + variance.z) / 3.0);
  return standardError / std::max((mean.x + mean.y + mean.z) / 3.0, 1e-3);
}

TEST_P(Adaptive, FlatPixelsStopEarlyNoisyOnesGoOnAndTheImageAgrees) {
  RadianceImage adaptive = render(adaptiveFlags());
  RadianceImage full = render({});
  ASSERT_EQ(adaptive.sampleCount.size(), adaptive.mean.size()) << "the EXR has no samples.X layer";
  EXPECT_TRUE(full.sampleCount.empty()) << "a render of every sample needs no count";

  size_t sky = 0, floor = 0;
  double floorSamples = 0.0;
  glm::dvec3 adaptiveSum(0.0), fullSum(0.0), varianceSum(0.0);
  for (size_t i = 0; i < adaptive.mean.size(); ++i) {
    const float n = adaptive.sampleCount[i];
    // The stopping rule: checked from the minimum on, every kInterval samples, and a pixel
    // that stopped before the end met the threshold then (its EXR values are that state's).
    ASSERT_GE(n, float(kMinSamples)) << "pixel " << i;
    ASSERT_LE(n, float(kSpp)) << "pixel " << i;
    EXPECT_EQ((uint32_t(n) - kMinSamples) % kInterval == 0 || n == float(kSpp), true) << "pixel " << i << ": " << n;
    if (n < float(kSpp)) EXPECT_LT(relativeError(adaptive, i), kThreshold * 1.001) << "pixel " << i << ": " << n;
    if (full.variance[i] == glm::vec3(0.0f)) {
      // The sky: one radiance in every sample, so it stops at the first check, with the
      // same value as the render of every sample.
      ++sky;
      EXPECT_EQ(n, float(kMinSamples)) << "pixel " << i;
      EXPECT_EQ(adaptive.mean[i], full.mean[i]) << "pixel " << i;
    } else {
      ++floor;
      floorSamples += n;
      adaptiveSum += glm::dvec3(adaptive.mean[i]);
      fullSum += glm::dvec3(full.mean[i]);
      varianceSum += glm::dvec3(adaptive.variance[i]);
    }
  }
  ASSERT_GT(sky, 100u);
  ASSERT_GT(floor, 100u);
  // The floor's noise keeps most of its pixels sampling well past the minimum.
  EXPECT_GT(floorSamples / double(floor), 3.0 * kMinSamples);
  // The floor's mean radiance agrees with the render of every sample: each pixel's adaptive
  // mean is a prefix of the full one's samples, so their difference is within the adaptive
  // mean's noise; z below 4 over the region.
  for (int c = 0; c < 3; ++c) {
    const double z = std::abs(adaptiveSum[c] - fullSum[c]) / std::sqrt(varianceSum[c]);
    EXPECT_LT(z, 4.0) << "channel " << c << ": " << adaptiveSum[c] / floor << " vs " << fullSum[c] / floor;
  }
}

TEST_P(Adaptive, TheImageDoesNotDependOnThePassSize) {
  std::vector<std::string> small = adaptiveFlags(), large = adaptiveFlags();
  small.insert(small.end(), {"--max-paths", "1000"});
  large.insert(large.end(), {"--max-paths", "65536"});
  RadianceImage a = render(small), b = render(large);
  ASSERT_EQ(a.mean.size(), b.mean.size());
  for (size_t i = 0; i < a.mean.size(); ++i) {
    ASSERT_EQ(a.mean[i], b.mean[i]) << "pixel " << i;
    ASSERT_EQ(a.variance[i], b.variance[i]) << "pixel " << i;
    ASSERT_EQ(a.sampleCount[i], b.sampleCount[i]) << "pixel " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Backend, Adaptive, ::testing::Values(std::string("vulkan"), std::string("opencl")),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace wp::test
