// End-to-end test of texture coordinate sets and KHR_texture_transform on both backends
// (Vulkan under validation), with tools/samples' texture-transform.gltf: quads that emit
// their texture, so every pixel shows the texel its transformed coordinates land on, which
// the test computes here from the extension's definition, independently of texture.h.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "samples/gltf_samples.h"
#include "support/render_exr.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

constexpr int kWidth = 64;  // 16 pixels per unit over x in [-2, 2], y in [-1, 1]
constexpr int kHeight = 32;

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// The texel (REPEAT, NEAREST) that the sample's quads show at the point (x, y), as
// KHR_texture_transform defines it: T(offset) R(rotation) S(scale) (u, v, 1), R's columns
// (cos, sin) and (-sin, cos).
glm::ivec2 texelAt(float x, float y) {
  glm::vec2 uv;
  if (x < 0.0f) {
    const glm::vec2 s = glm::vec2((x + 2.0f) / 2.0f, (1.0f - y) / 2.0f) * samples::kTransformScale;
    const float c = std::cos(samples::kTransformRotation), n = std::sin(samples::kTransformRotation);
    uv = glm::vec2(c * s.x - n * s.y, n * s.x + c * s.y) + samples::kTransformOffset;
  } else {
    uv = glm::vec2(x / 2.0f, (1.0f - y) / 2.0f) + samples::kSecondSetOffset;
  }
  const glm::ivec2 t(glm::floor(uv * 4.0f));
  return ((t % 4) + 4) % 4;
}

class TextureTransform : public ::testing::TestWithParam<std::string> {};

// Every pixel whose area lies within one texel (its four corners agree) shows that texel
// exactly: the emission is the texel, with no noise.
TEST_P(TextureTransform, TexelsLandWhereTheTransformSays) {
  const RadianceImage image =
      renderExr(GetParam(), samples::writeTextureTransform(scratchDirectory("texture-transform")),
                {"--width", std::to_string(kWidth), "--height", std::to_string(kHeight), "--spp", "4", "--sky", "none"});
  ASSERT_EQ(image.width, uint32_t(kWidth));
  int checked = 0;
  for (int py = 0; py < kHeight; ++py) {
    for (int px = 0; px < kWidth; ++px) {
      const auto corner = [&](int dx, int dy) {
        return texelAt(-2.0f + float(px + dx) / 16.0f, 1.0f - float(py + dy) / 16.0f);
      };
      const glm::ivec2 t = corner(0, 0);
      // Corners nudged inwards: a pixel edge on the quads' seam (x = 0) belongs to both.
      if (px % 32 == 31 || corner(1, 0) != t || corner(0, 1) != t || corner(1, 1) != t) continue;
      const glm::vec3 srgb = glm::vec3(samples::transformTestTexel(t.x, t.y)) / 255.0f;
      const glm::vec3 expected(srgbToLinear(srgb.r), srgbToLinear(srgb.g), srgbToLinear(srgb.b));
      const glm::vec3 got = image.mean[size_t(py) * kWidth + size_t(px)];
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], expected[c], 1e-3) << "pixel " << px << ", " << py << " should show texel " << t.x << ", "
                                               << t.y;
      }
      ++checked;
    }
  }
  // Most pixels lie within a texel; the test must not pass by checking none.
  EXPECT_GT(checked, kWidth * kHeight / 2);
}

INSTANTIATE_TEST_SUITE_P(Backend, TextureTransform, ::testing::Values(std::string("vulkan"), std::string("opencl")),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace wp::test
