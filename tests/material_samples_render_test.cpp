// The material extensions' sample files (tools/samples: a row of spheres per extension)
// rendered with and without their extension: each extension must change the image the way its
// model says, so a loader or shader that dropped it fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "samples/gltf_samples.h"
#include "support/image_stats.h"
#include "support/render_exr.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

using samples::MaterialExtension;

// Direct light only, from the samples' directional lamp, with the same seed in both files.
RadianceImage renderSpheres(const std::string& backend, MaterialExtension extension, bool withExtension) {
  const std::filesystem::path dir =
      scratchDirectory("material-samples-" + backend + (withExtension ? "-with" : "-without"));
  return renderExr(backend, samples::writeMaterialSpheres(dir, extension, withExtension),
                   {"--width", "64", "--height", "24", "--spp", "16", "--sky", "none", "--max-depth", "0"});
}

struct Summary {
  glm::dvec3 mean{0.0};
  glm::dvec3 brightest{0.0};  // per channel, over the pixels
};

// Over the pixels of columns firstColumn and right of it (all: the whole image).
Summary summarize(const RadianceImage& image, uint32_t firstColumn = 0) {
  Summary s;
  const double pixels = double(image.height) * double(image.width - firstColumn);
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = firstColumn; x < image.width; ++x) {
      const glm::dvec3 pixel(image.mean[size_t(y) * image.width + x]);
      s.mean += pixel / pixels;
      s.brightest = glm::max(s.brightest, pixel);
    }
  }
  return s;
}

// The fraction of pixels where some channel differs by more than 0.01.
double changedFraction(const RadianceImage& a, const RadianceImage& b) {
  size_t changed = 0;
  for (size_t i = 0; i < a.mean.size(); ++i) {
    const glm::vec3 d = glm::abs(a.mean[i] - b.mean[i]);
    changed += std::max({d.x, d.y, d.z}) > 0.01f ? 1 : 0;
  }
  return double(changed) / double(a.mean.size());
}

class MaterialSamples : public ::testing::TestWithParam<std::string> {};

// KHR_materials_unlit: the spheres show exactly their base colours (the brightest pixel of
// each channel is the largest base colour of that channel: 0.9, 0.9, 0.2), which a lit
// sphere under a 1500-lux lamp does not.
TEST_P(MaterialSamples, UnlitSpheresShowTheirBaseColours) {
  const RadianceImage with = renderSpheres(GetParam(), MaterialExtension::Unlit, true);
  const RadianceImage without = renderSpheres(GetParam(), MaterialExtension::Unlit, false);
  const Summary s = summarize(with);
  EXPECT_NEAR(s.brightest.x, 0.9, 1e-4);
  EXPECT_NEAR(s.brightest.y, 0.9, 1e-4);
  EXPECT_NEAR(s.brightest.z, 0.2, 1e-4);
  EXPECT_GT(changedFraction(with, without), 0.1);
}

// KHR_materials_sheen: a pale pink sheen (1, 0.6, 0.8) over dark blue cloth adds light,
// most towards the rims: every channel gets brighter, red (where the cloth reflects 0.05
// and the sheen most) at least twice. (The blue gains least: the sheen takes its share of
// what reaches the blue base.)
TEST_P(MaterialSamples, SheenBrightensDarkCloth) {
  const Summary with = summarize(renderSpheres(GetParam(), MaterialExtension::Sheen, true));
  const Summary without = summarize(renderSpheres(GetParam(), MaterialExtension::Sheen, false));
  std::printf("sheen: mean %.4f %.4f %.4f, without %.4f %.4f %.4f\n", with.mean.x, with.mean.y, with.mean.z,
              without.mean.x, without.mean.y, without.mean.z);
  for (int c = 0; c < 3; ++c) EXPECT_GT(with.mean[c], 1.2 * without.mean[c]) << "channel " << c;
  EXPECT_GT(with.mean.x, 2.0 * without.mean.x);
}

// KHR_materials_clearcoat: a white glossy highlight on rough red plastic, whose own highlight
// is broad and dim: the brightest green (which the red base hardly reflects) rises.
TEST_P(MaterialSamples, ClearcoatAddsAWhiteHighlight) {
  const Summary with = summarize(renderSpheres(GetParam(), MaterialExtension::Clearcoat, true));
  const Summary without = summarize(renderSpheres(GetParam(), MaterialExtension::Clearcoat, false));
  std::printf("clearcoat: brightest green %.4f, without %.4f\n", with.brightest.y, without.brightest.y);
  EXPECT_GT(with.brightest.y, 2.0 * without.brightest.y);
}

// KHR_materials_clearcoat's clearcoatNormalTexture: the fourth sphere's coat has ripples
// along u, which break its highlight into stripes; the same file with the texture's key
// renamed (so the coat lies on the shading normal) renders a different highlight there.
TEST_P(MaterialSamples, ClearcoatNormalTextureRipplesTheCoat) {
  const std::filesystem::path dir = scratchDirectory("material-samples-coat-normal-" + GetParam());
  const std::filesystem::path rippled = samples::writeMaterialSpheres(dir, MaterialExtension::Clearcoat, true);
  std::string text;
  {
    std::ifstream in(rippled);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const size_t key = text.find("\"clearcoatNormalTexture\"");
  ASSERT_NE(key, std::string::npos);
  text.replace(key, std::string("\"clearcoatNormalTexture\"").size(), "\"notANormalTexture\"");
  const std::filesystem::path flat = dir / "clearcoat-spheres-flat.gltf";
  std::ofstream(flat) << text;
  const std::vector<std::string> flags = {"--width", "128", "--height", "48", "--spp", "16", "--sky", "none",
                                          "--max-depth", "0"};
  const RadianceImage a = renderExr(GetParam(), rippled, flags);
  const RadianceImage b = renderExr(GetParam(), flat, flags);
  const double changed = changedFraction(a, b);
  std::printf("coat normal texture: %.4f of the pixels changed\n", changed);
  EXPECT_GT(changed, 0.005);
}

// KHR_materials_specular: an orange specularColorFactor (1, 0.6, 0.2) over blue plastic turns
// the highlights orange: they lose blue (glTF's white layer reflects blue as much as red) and
// keep red (F0 red stays 0.04 on the fourth sphere, of specularFactor 1). Both are read on
// the fourth sphere alone (the right quarter of the image): without the extension all four
// spheres have the same highlight, and the brightest of four sub-pixel placements of a small
// highlight is not the fourth's.
TEST_P(MaterialSamples, SpecularTintsTheHighlight) {
  const RadianceImage withImage = renderSpheres(GetParam(), MaterialExtension::Specular, true);
  const uint32_t fourthSphere = withImage.width * 3 / 4;
  const Summary with = summarize(withImage, fourthSphere);
  const Summary without = summarize(renderSpheres(GetParam(), MaterialExtension::Specular, false), fourthSphere);
  std::printf("specular: brightest %.4f %.4f %.4f, without %.4f %.4f %.4f\n", with.brightest.x, with.brightest.y,
              with.brightest.z, without.brightest.x, without.brightest.y, without.brightest.z);
  EXPECT_LT(with.brightest.z, 0.75 * without.brightest.z);
  EXPECT_NEAR(with.brightest.x, without.brightest.x, 0.05 * without.brightest.x);
}

INSTANTIATE_TEST_SUITE_P(Backend, MaterialSamples, ::testing::Values("vulkan", "opencl"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace wp::test
