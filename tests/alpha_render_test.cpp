// End-to-end tests of glTF alphaMode on both backends (Vulkan under validation), with the
// sample files of tools/samples: a MASK quad's cut-out texels show the emitter behind it and
// its opaque ones hide it; a BLEND pane of alpha 0.25 lets 0.75 of it through to the camera;
// and a BLEND pane's shadow keeps 0.75 of the sunlight (shadow rays see alpha too).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "samples/gltf_samples.h"
#include "support/render_exr.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

constexpr int kSpp = 16;

// The mean over columns [x0, x1) and rows [y0, y1) of the green channel (the scenes are grey).
double regionMean(const RadianceImage& image, int x0, int x1, int y0, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) sum += image.mean[size_t(y) * image.width + size_t(x)].g;
  }
  return sum / double((x1 - x0) * (y1 - y0));
}

class Alpha : public ::testing::TestWithParam<std::string> {};

// 64x32 pixels over the sample's 4 x 2 units: the MASK quad's texels are 8x8 pixels in the
// left half, the BLEND pane fills the right half.
TEST_P(Alpha, MaskCutsOutAndBlendLetsThroughOneMinusAlpha) {
  const RadianceImage image =
      renderExr(GetParam(), samples::writeAlphaCoverage(scratchDirectory("alpha-coverage")),
                {"--width", "64", "--height", "32", "--spp", std::to_string(kSpp), "--sky", "none"});
  ASSERT_EQ(image.width, 64u);
  // Texel (x, y) has alpha 1 where x + y is even: black there, the emitter's 1 elsewhere.
  // Pixels a pixel away from a texel's edge see only that texel (the box filter's jitter
  // stays in the pixel), so each is exactly 0 or 1.
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      if (x % 8 == 0 || x % 8 == 7 || y % 8 == 0 || y % 8 == 7) continue;
      const bool opaque = (x / 8 + y / 8) % 2 == 0;
      EXPECT_NEAR(image.mean[size_t(y) * 64 + size_t(x)].g, opaque ? 0.0 : 1.0, 1e-4) << "pixel " << x << ", " << y;
    }
  }
  // The pane's alpha is 0.5 (factor) x 128/255 (COLOR_0 as stored, RGBA8): each sample sees
  // the emitter with probability 1 - alpha. Over 1024 pixels x 16 samples the mean's
  // standard deviation is sqrt(0.75 x 0.25 / 16384) = 0.0034; the bound is 6 of them. An
  // opaque pane gives 0, one that ignores the alpha's COLOR_0 factor 0.5.
  const double alpha = 0.5 * 128.0 / 255.0;
  EXPECT_NEAR(regionMean(image, 32, 64, 0, 32), 1.0 - alpha, 0.02);
}

// 32x16 pixels over x in [0, 2]: columns below 16 lie in the pane's shadow, the rest in sun.
TEST_P(Alpha, ShadowThroughBlendKeepsOneMinusAlpha) {
  const RadianceImage image =
      renderExr(GetParam(), samples::writeAlphaShadow(scratchDirectory("alpha-shadow")),
                {"--width", "32", "--height", "16", "--spp", std::to_string(kSpp), "--sky", "none", "--max-depth", "0"});
  ASSERT_EQ(image.width, 32u);
  // Direct sunlight only: the lit floor is the same everywhere, each shadowed sample keeps
  // it with probability 0.75. 13 x 16 pixels x 16 samples: the ratio's standard deviation is
  // sqrt(0.75 x 0.25 / 3328) / 0.75 = 0.010; the bound is 4 of them. An opaque pane gives 0,
  // one that shadow rays ignore 1. The columns by the shadow's edge (x = 1) are left out.
  const double lit = regionMean(image, 18, 31, 0, 16);
  ASSERT_GT(lit, 0.01);
  EXPECT_NEAR(regionMean(image, 1, 14, 0, 16) / lit, 0.75, 0.04);
}

INSTANTIATE_TEST_SUITE_P(Backend, Alpha, ::testing::Values(std::string("vulkan"), std::string("opencl")),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace wp::test
