// End-to-end tests of the ways glTF stores vertex data: a sparse accessor renders as its
// dense twin, and Draco- and meshopt-compressed files (written by tools/samples with the
// Debian libraries' encoders) render as their uncompressed original, within quantization.
// The loader hands both backends the same scene, so Vulkan (under validation) suffices.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "samples/gltf_samples.h"
#include "support/render_exr.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

// Direct light only from the samples' directional lamp, with the same seed: every pixel's
// samples hit the same places in two files of the same geometry, so the images agree
// exactly, or up to the quantization's shifts of edges and texel boundaries.
RadianceImage renderSample(const std::filesystem::path& file) {
  return renderExr("vulkan", file,
                   {"--width", "48", "--height", "48", "--spp", "4", "--sky", "none", "--max-depth", "0"});
}

struct Difference {
  double meanRatio = 0.0;      // mean of a over mean of b (all channels)
  double largeFraction = 0.0;  // pixels where a channel differs by more than 0.01
};

Difference compare(const RadianceImage& a, const RadianceImage& b) {
  double sumA = 0.0, sumB = 0.0;
  size_t large = 0;
  for (size_t i = 0; i < a.mean.size(); ++i) {
    bool differs = false;
    for (int c = 0; c < 3; ++c) {
      sumA += a.mean[i][c];
      sumB += b.mean[i][c];
      differs = differs || std::abs(a.mean[i][c] - b.mean[i][c]) > 0.01f;
    }
    large += differs ? 1 : 0;
  }
  return {sumA / sumB, double(large) / double(a.mean.size())};
}

TEST(GltfData, SparseAccessorRendersAsItsDenseTwin) {
  const std::filesystem::path dir = scratchDirectory("sparse-grid");
  const RadianceImage sparse = renderSample(samples::writeSparseGrid(dir, true));
  const RadianceImage dense = renderSample(samples::writeSparseGrid(dir, false));
  ASSERT_EQ(sparse.mean.size(), dense.mean.size());
  // The same positions: the same image, bit for bit up to float noise.
  const Difference d = compare(sparse, dense);
  EXPECT_NEAR(d.meanRatio, 1.0, 1e-5);
  EXPECT_EQ(d.largeFraction, 0.0);
}

class Compressed : public ::testing::TestWithParam<samples::Compression> {};

TEST_P(Compressed, RendersAsTheUncompressedOriginal) {
  const std::filesystem::path dir = scratchDirectory("compressed");
  const RadianceImage plain = renderSample(samples::writeCompressedSphere(dir, samples::Compression::None));
  const RadianceImage compressed = renderSample(samples::writeCompressedSphere(dir, GetParam()));
  ASSERT_EQ(plain.mean.size(), compressed.mean.size());
  // Draco's 12-bit texture coordinates move texel boundaries by up to 1/8192 of the texture
  // and its 14-bit positions the silhouette by 1e-4: a few samples on those edges change
  // colour. Measured for Draco: 0.04% on the mean, 0.2% of the pixels; meshopt's 16 bits
  // change nothing visible. The bounds are about ten times that; a decoding error changes
  // the sphere's outline, shading or texture over far more of it.
  const Difference d = compare(compressed, plain);
  EXPECT_NEAR(d.meanRatio, 1.0, 0.003);
  EXPECT_LT(d.largeFraction, 0.02);
}

INSTANTIATE_TEST_SUITE_P(Codec, Compressed,
                         ::testing::Values(samples::Compression::Draco, samples::Compression::Meshopt),
                         [](const ::testing::TestParamInfo<samples::Compression>& info) {
                           return info.param == samples::Compression::Draco ? "Draco" : "Meshopt";
                         });

}  // namespace
}  // namespace wp::test
