// End-to-end renders on both backends (lavapipe and PoCL in CI), Vulkan with the
// validation layer on: furnace, agreement of the three light-sampling strategies,
// determinism, and agreement of the two backends with each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "image/image_io.h"
#include "samples/gltf_samples.h"
#include "support/gltf_writer.h"
#include "support/image_stats.h"
#include "support/render_exr.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

// The estimator tests run once per backend; the test name ends in the backend's name.
class BackendTest : public ::testing::TestWithParam<std::string> {
protected:
  RadianceImage render(const std::filesystem::path& scene, const std::vector<std::string>& flags) {
    return renderExr(GetParam(), scene, flags);
  }
};
class Furnace : public BackendTest {};
class CornellBox : public BackendTest {};
class Determinism : public BackendTest {};

std::string backendName(const ::testing::TestParamInfo<std::string>& info) { return info.param; }

// Inside a closed surface that emits L and reflects diffusely with albedo a, radiance is
// L / (1 - a) everywhere. With at most D + 2 segments the path sum is truncated to
// L (1 - a^(D+2)) / (1 - a).
TEST_P(Furnace, ClosedEmissiveSphereConvergesToLOverOneMinusAlbedo) {
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
      // The 1% bound; the estimate's own noise must be well inside it (3 standard
      // errors) to mean anything. With NEE the standard error is itself noisy: a light
      // sample on a facet next to the shading point's is near-singular (heavy-tailed), so
      // over seeds 0 to 11 it measured 0.0010 to 0.0027 of the expected value (both samplers).
      EXPECT_LT(m.standardError[c], 0.0033 * expected) << "channel " << c;
      EXPECT_NEAR(m.mean[c], expected, 0.01 * expected) << "channel " << c;
    }
  }
}

// MIS, NEE-only and BSDF-only are unbiased estimators of the same image: their image means
// must agree within noise. Statistic: z = |mean_a - mean_b| / sqrt(se_a^2 + se_b^2) per
// channel, accepted below 4 (two-sided p = 6e-5, so 9 comparisons almost never fail by
// chance while a bias of a few standard errors is caught).
TEST_P(CornellBox, MisNeeAndBsdfSamplingAgreeInMeanRadiance) {
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
        double se = differenceError(means[a], means[b], c);
        double z = meanZ(means[a], means[b], c);
        EXPECT_LT(z, 4.0) << "modes " << a << " and " << b << ", channel " << c << ": " << means[a].mean[c]
                          << " vs " << means[b].mean[c] << " (se " << se << ")";
        // The comparison is only sharp if the noise is small against the signal.
        EXPECT_LT(se, 0.02 * means[0].mean[c]);
      }
    }
  }
}

// Light selection by solid angle changes only the variance: with it, MIS and NEE-only agree
// with NEE-only under the default selection by power (same statistic as above).
TEST_P(CornellBox, SolidAngleLightSelectionAgreesWithSelectionByPower) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  std::vector<std::vector<std::string>> runs = {{"--mode", "nee"},
                                                {"--mode", "nee", "--light-selection", "solid-angle"},
                                                {"--mode", "mis", "--light-selection", "solid-angle"}};
  std::vector<ImageMean> means;
  for (std::vector<std::string> flags : runs) {
    flags.insert(flags.end(), {"--width", "48", "--height", "48", "--spp", "128", "--max-depth", "8"});
    means.push_back(imageMean(render(scene, flags)));
  }
  for (size_t a = 1; a < means.size(); ++a) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_LT(meanZ(means[0], means[a], c), 4.0)
          << "run " << a << ", channel " << c << ": " << means[0].mean[c] << " vs " << means[a].mean[c];
      EXPECT_LT(differenceError(means[0], means[a], c), 0.02 * means[0].mean[c]);
    }
  }
}

// Relative RMSE of `image` against `reference` over all pixels and channels:
// sqrt(sum of squared errors / sum of squared reference values).
double relativeRmse(const RadianceImage& image, const RadianceImage& reference) {
  double squaredError = 0.0, squaredReference = 0.0;
  for (size_t i = 0; i < image.mean.size(); ++i) {
    const glm::dvec3 error = glm::dvec3(image.mean[i]) - glm::dvec3(reference.mean[i]);
    squaredError += glm::dot(error, error);
    squaredReference += glm::dot(glm::dvec3(reference.mean[i]), glm::dvec3(reference.mean[i]));
  }
  return std::sqrt(squaredError / squaredReference);
}

// The Sobol sampler (the default) stratifies each pixel's samples: at equal samples its image
// is closer to Cycles' 4096-spp Lambertian box (tests/data/cornell-cycles-64.exr, box-averaged
// to 64x64: its own noise is negligible here) than the independent sampler's, and it stays
// unbiased (the means agree by expectAgreement's z test). At 16 spp it measures 0.57 of the
// independent sampler's error on both backends (the light's edges weigh most); each is a
// ratio of two RMSEs over 12288 pixel-channels, whose noise is a few percent, so 0.8
// separates the two samplers with room while a sampler that stratifies nothing (near 1) fails.
TEST_P(CornellBox, SobolSamplerIsUnbiasedAndCloserToTheReferenceThanIndependentSampling) {
  const RadianceImage reference = readExr(sourceDirectory() / "tests" / "data" / "cornell-cycles-64.exr");
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  std::vector<ImageMean> means;
  std::vector<double> errors;
  for (const char* sampler : {"sobol", "independent"}) {
    RadianceImage image = render(scene, {"--width", "64", "--height", "64", "--spp", "16", "--max-depth", "8",
                                         "--sampler", sampler});
    ASSERT_EQ(image.mean.size(), reference.mean.size());
    means.push_back(imageMean(image));
    errors.push_back(relativeRmse(image, reference));
  }
  std::printf("relative RMSE at 16 spp: sobol %.4f, independent %.4f (ratio %.3f)\n", errors[0], errors[1],
              errors[0] / errors[1]);
  EXPECT_LT(errors[0], 0.8 * errors[1]);
  expectAgreement(means, {"sobol", "independent"});
}

TEST_P(Determinism, SameSeedGivesTheSameImageAndAnotherSeedDoesNot) {
  std::filesystem::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  auto flags = [](const std::string& seed) {
    return std::vector<std::string>{"--width", "40", "--height", "30", "--spp", "8", "--seed", seed};
  };
  RadianceImage first = render(scene, flags("7"));
  // A different paths-in-flight bound splits the work into other passes, and OpenCL sizes
  // its launches the other way (Vulkan ignores --cl-dispatch): still the same image.
  std::vector<std::string> split = flags("7");
  split.insert(split.end(), {"--max-paths", "1000", "--cl-dispatch", "max"});
  RadianceImage second = render(scene, split);
  ASSERT_EQ(first.mean.size(), second.mean.size());
  for (size_t i = 0; i < first.mean.size(); ++i) {
    ASSERT_EQ(first.mean[i], second.mean[i]) << "pixel " << i;
  }
  RadianceImage other = render(scene, flags("8"));
  size_t differing = 0;
  for (size_t i = 0; i < first.mean.size(); ++i) {
    differing += first.mean[i] != other.mean[i];
  }
  EXPECT_GT(differing, first.mean.size() / 2);
}

const auto kBackends = ::testing::Values(std::string("vulkan"), std::string("opencl"));
INSTANTIATE_TEST_SUITE_P(Backend, Furnace, kBackends, backendName);
INSTANTIATE_TEST_SUITE_P(Backend, CornellBox, kBackends, backendName);
INSTANTIATE_TEST_SUITE_P(Backend, Determinism, kBackends, backendName);

// Both backends run the same estimator on the same random numbers, so with the same seed
// they must render the same image up to floating-point rounding (their sin, cos, sqrt and
// fused multiply-adds may differ in the last bits, which now and then sends a path another
// way, e.g. past a triangle's edge or a Russian-roulette threshold). Three checks:
// - the image means agree within 0.5% per channel;
// - no local bias: per pixel and channel z = (a - b) / sqrt(var_a + var_b), with the
//   variances of the means from the EXRs' variance AOV. Even if the two images were
//   independent renders of the same expectation, |z| > 3 would happen with probability
//   0.0027; the count of such pixel-channels is accepted up to the one-sided 0.1% point of
//   that binomial (normal approximation), so the test fails by chance less than once in a
//   thousand runs while a biased region of a few dozen pixels fails it;
// - the same estimator: independent renders would give a median |z| of 0.67, identical
//   random decisions a median near 0. A median below 0.05 shows that the backends drew the
//   same samples, which a mean test alone cannot tell from a different unbiased estimator.
void expectBackendsAgree(const std::filesystem::path& scene, const std::vector<std::string>& flags) {
  SCOPED_TRACE(scene.filename().string());
  RadianceImage vulkan = renderExr("vulkan", scene, flags);
  RadianceImage opencl = renderExr("opencl", scene, flags);
  ASSERT_EQ(vulkan.mean.size(), opencl.mean.size());

  ImageMean a = imageMean(vulkan);
  ImageMean b = imageMean(opencl);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(b.mean[c], a.mean[c], 0.005 * a.mean[c]) << "channel " << c;
  }

  std::vector<double> absZ;
  size_t beyond3 = 0;
  for (size_t i = 0; i < vulkan.mean.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      double difference = double(vulkan.mean[i][c]) - double(opencl.mean[i][c]);
      double variance = double(vulkan.variance[i][c]) + double(opencl.variance[i][c]);
      // Pixels without variance (all samples equal, e.g. on the light) must match exactly.
      double z = variance > 0.0 ? std::abs(difference) / std::sqrt(variance) : (difference == 0.0 ? 0.0 : INFINITY);
      absZ.push_back(z);
      beyond3 += z > 3.0;
    }
  }
  const double n = double(absZ.size());
  const double p = 0.0027;
  const double bound = n * p + 3.09 * std::sqrt(n * p * (1.0 - p));
  EXPECT_LE(double(beyond3), bound) << beyond3 << " of " << absZ.size() << " pixel-channels with |z| > 3";
  std::nth_element(absZ.begin(), absZ.begin() + absZ.size() / 2, absZ.end());
  EXPECT_LT(absZ[absZ.size() / 2], 0.05) << "median |z|";
}

TEST(BackendAgreement, VulkanAndOpenClRenderTheSameImageFromTheSameSeed) {
  expectBackendsAgree(sourceDirectory() / "assets" / "cornell-box.gltf",
                      {"--width", "64", "--height", "64", "--spp", "64", "--seed", "5", "--max-depth", "8"});
}

// glTF's BRDF reads the BSDF tables (bsdf_table_lookup.h), which Vulkan fetches from texels
// the host packs and OpenCL from the header's array: the dielectric's layering reads both GGX
// tables and both of their means, a rough metal the white table and mean
// (energy_compensation.h), sheen its own table. A texel packed from the wrong entries shifts
// Vulkan's image alone.
TEST(BackendAgreement, GltfMaterialsReadTheSameBsdfTablesOnBothBackends) {
  expectBackendsAgree(sourceDirectory() / "assets" / "materials.gltf",
                      {"--width", "64", "--height", "48", "--spp", "32", "--seed", "5", "--max-depth", "8"});
  const std::filesystem::path sheen =
      samples::writeMaterialSpheres(scratchDirectory("agreement-sheen"), samples::MaterialExtension::Sheen, true);
  expectBackendsAgree(sheen, {"--width", "64", "--height", "24", "--spp", "32", "--seed", "5", "--sky", "none"});
}

}  // namespace
}  // namespace wp::test
