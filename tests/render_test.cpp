// End-to-end renders on the Vulkan backend (lavapipe in CI) with the validation layer on:
// furnace, agreement of the three light-sampling strategies, determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "image/image_io.h"
#include "support/gltf_writer.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

// Mean radiance over the image and its standard error. Pixels are independent, so the
// variance of the mean is the sum of the per-pixel variances (the EXR's variance AOV)
// divided by the squared pixel count.
struct ImageMean {
  glm::dvec3 mean{0.0};
  glm::dvec3 standardError{0.0};
};

ImageMean imageMean(const RadianceImage& image) {
  ImageMean m;
  glm::dvec3 varianceSum(0.0);
  for (size_t i = 0; i < image.mean.size(); ++i) {
    m.mean += glm::dvec3(image.mean[i]);
    varianceSum += glm::dvec3(image.variance[i]);
  }
  double n = double(image.mean.size());
  m.mean /= n;
  m.standardError = glm::sqrt(varianceSum) / n;
  return m;
}

RadianceImage render(const std::filesystem::path& scene, const std::vector<std::string>& flags) {
  std::filesystem::path out = scratchDirectory("render") / "image.exr";
  std::vector<std::string> args = {"render", scene.string(), "-o", out.string()};
  args.insert(args.end(), flags.begin(), flags.end());
  RunResult r = runWavepath(args);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
  return readExr(out);
}

// Inside a closed surface that emits L and reflects diffusely with albedo a, radiance is
// L / (1 - a) everywhere. With at most D + 2 segments the path sum is truncated to
// L (1 - a^(D+2)) / (1 - a).
TEST(Furnace, ClosedEmissiveSphereConvergesToLOverOneMinusAlbedo) {
  const glm::dvec3 albedo(0.5, 0.3, 0.8);
  const double emitted = 0.5;
  const int maxBounces = 40;
  TestScene scene;
  scene.materials.push_back({glm::vec3(albedo), glm::vec3(float(emitted)), true});
  scene.meshes.push_back(icosphere(1.0f, 2));
  scene.camera.position = glm::vec3(0.1f, -0.2f, 0.3f);
  std::filesystem::path file = writeGltf(scene, scratchDirectory("furnace") / "furnace.gltf");

  for (const char* mode : {"mis", "nee", "bsdf"}) {
    SCOPED_TRACE(mode);
    RadianceImage image = render(file, {"--width", "48", "--height", "48", "--spp", "64", "--max-depth",
                                        std::to_string(maxBounces), "--mode", mode});
    ImageMean m = imageMean(image);
    for (int c = 0; c < 3; ++c) {
      double expected = emitted * (1.0 - std::pow(albedo[c], maxBounces + 2)) / (1.0 - albedo[c]);
      // The 1% bound; the estimate's own noise must be well inside it to mean anything.
      EXPECT_LT(m.standardError[c], 0.0025 * expected) << "channel " << c;
      EXPECT_NEAR(m.mean[c], expected, 0.01 * expected) << "channel " << c;
    }
  }
}

// MIS, NEE-only and BSDF-only are unbiased estimators of the same image: their image means
// must agree within noise. Statistic: z = |mean_a - mean_b| / sqrt(se_a^2 + se_b^2) per
// channel, accepted below 4 (two-sided p = 6e-5, so 9 comparisons almost never fail by
// chance while a bias of a few standard errors is caught).
TEST(CornellBox, MisNeeAndBsdfSamplingAgreeInMeanRadiance) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  std::vector<ImageMean> means;
  for (const char* mode : {"mis", "nee", "bsdf"}) {
    RadianceImage image =
        render(scene, {"--width", "48", "--height", "48", "--spp", "128", "--max-depth", "8", "--mode", mode});
    means.push_back(imageMean(image));
  }
  for (size_t a = 0; a < means.size(); ++a) {
    for (size_t b = a + 1; b < means.size(); ++b) {
      for (int c = 0; c < 3; ++c) {
        double se = std::sqrt(means[a].standardError[c] * means[a].standardError[c] +
                              means[b].standardError[c] * means[b].standardError[c]);
        double z = std::abs(means[a].mean[c] - means[b].mean[c]) / se;
        EXPECT_LT(z, 4.0) << "modes " << a << " and " << b << ", channel " << c << ": " << means[a].mean[c]
                          << " vs " << means[b].mean[c] << " (se " << se << ")";
        // The comparison is only sharp if the noise is small against the signal.
        EXPECT_LT(se, 0.02 * means[0].mean[c]);
      }
    }
  }
}

TEST(Determinism, SameSeedGivesTheSameImageAndAnotherSeedDoesNot) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  std::vector<std::string> flags = {"--width", "40", "--height", "30", "--spp", "8", "--seed", "7"};
  RadianceImage first = render(scene, flags);
  // A different paths-in-flight bound splits the work into other passes: still the same image.
  std::vector<std::string> split = flags;
  split.insert(split.end(), {"--max-paths", "1000"});
  RadianceImage second = render(scene, split);
  ASSERT_EQ(first.mean.size(), second.mean.size());
  for (size_t i = 0; i < first.mean.size(); ++i) {
    ASSERT_EQ(first.mean[i], second.mean[i]) << "pixel " << i;
  }
  flags[7] = "8";
  RadianceImage other = render(scene, flags);
  size_t differing = 0;
  for (size_t i = 0; i < first.mean.size(); ++i) {
    differing += first.mean[i] != other.mean[i];
  }
  EXPECT_GT(differing, first.mean.size() / 2);
}

}  // namespace
}  // namespace wp::test
