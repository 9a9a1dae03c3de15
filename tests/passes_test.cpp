// The feature passes of an analytic scene on both backends (lavapipe under validation,
// PoCL): a diffuse wall facing the camera, a tilted glTF plane, a perfect mirror that shows
// a wall behind the camera, and the sky, each pass compared with its known value; --passes
// selects the EXR's channels.
#include <gtest/gtest.h>

#include <cmath>

#include "image/image_io.h"
#include "support/gltf_writer.h"
#include "support/render_exr.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

constexpr uint32_t kSize = 32;
constexpr float kTanHalfFov = 0.42279322f;  // tan(0.4): the test camera's yfov is 0.8

// A quad with corners a, b, c, d (counter-clockwise seen from its front).
TestMesh quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, int material) {
  TestMesh m;
  m.positions = {a, b, c, d};
  m.indices = {0, 1, 2, 0, 2, 3};
  m.material = material;
  return m;
}

// The camera at the origin looking down -z. In view: the back wall at z = -4 (up to y = 0.5,
// the sky above it), a mirror at z = -2 facing the camera, a glTF plane tilted towards +y;
// behind the camera, a wall facing -z that the mirror shows.
std::filesystem::path passesScene() {
  TestScene s;
  s.materials.push_back({glm::vec3(0.2f, 0.5f, 0.8f)});  // 0: back wall, Lambert
  s.materials.push_back({glm::vec3(0.1f, 0.7f, 0.2f)});  // 1: wall behind the camera
  TestMaterial mirror;
  mirror.lambert = false;
  mirror.metallic = 1.0f;
  mirror.roughness = 0.0f;
  s.materials.push_back(mirror);  // 2
  TestMaterial tilted;
  tilted.baseColor = glm::vec3(0.9f, 0.8f, 0.1f);
  tilted.lambert = false;
  tilted.roughness = 0.5f;
  s.materials.push_back(tilted);  // 3
  s.meshes.push_back(quad({-5, -5, -4}, {5, -5, -4}, {5, 0.5f, -4}, {-5, 0.5f, -4}, 0));
  s.meshes.push_back(quad({10, -10, 3}, {-10, -10, 3}, {-10, 10, 3}, {10, 10, 3}, 1));
  s.meshes.push_back(quad({0.2f, -0.3f, -2}, {0.8f, -0.3f, -2}, {0.8f, 0.3f, -2}, {0.2f, 0.3f, -2}, 2));
  // Through (0, -0.8, -3) with normal (0, 0.6, 0.8).
  s.meshes.push_back(quad({-0.4f, -1.2f, -2.7f}, {0.4f, -1.2f, -2.7f}, {0.4f, -0.5f, -3.225f},
                          {-0.4f, -0.5f, -3.225f}, 3));
  return writeGltf(s, scratchDirectory("passes") / "passes.gltf");
}

// The pixel (row-major index) whose footprint holds the image of world point p.
size_t pixelOf(glm::vec3 p) {
  const float ndcX = p.x / (-p.z * kTanHalfFov), ndcY = p.y / (-p.z * kTanHalfFov);
  const auto column = size_t((ndcX + 1.0f) / 2.0f * kSize), row = size_t((1.0f - ndcY) / 2.0f * kSize);
  return row * kSize + column;
}

class Passes : public ::testing::TestWithParam<std::string> {};

// Every sample of these pixels sees the same surface, so the means are the values
// themselves up to float rounding of the sums: 1e-5, relative for the depth.
void expectPasses(const RadianceImage& image, glm::vec3 at, glm::vec3 albedo, glm::vec3 normal,
                  const char* what) {
  SCOPED_TRACE(what);
  const size_t i = pixelOf(at);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(image.albedo[i][c], albedo[c], 1e-5) << "albedo channel " << c;
    EXPECT_NEAR(image.normal[i][c], normal[c], 1e-5) << "normal channel " << c;
  }
}

TEST_P(Passes, AnalyticSceneHasItsKnownAlbedoNormalAndDepth) {
  RadianceImage image = renderExr(GetParam(), passesScene(),
                                  {"--width", std::to_string(kSize), "--height", std::to_string(kSize), "--spp", "16",
                                   "--sky-color", "0.3,0.6,0.9"});
  ASSERT_EQ(image.albedo.size(), image.mean.size());
  ASSERT_EQ(image.normal.size(), image.mean.size());
  ASSERT_EQ(image.depth.size(), image.mean.size());

  const glm::vec3 wall(-0.8f, -0.8f, -4.0f), mirror(0.5f, 0.0f, -2.0f), sky(-0.8f, 1.4f, -4.0f);
  expectPasses(image, wall, {0.2f, 0.5f, 0.8f}, {0, 0, 1}, "the back wall");
  // The depth pass is along the camera's axis: a plane facing the camera has one depth.
  EXPECT_NEAR(image.depth[pixelOf(wall)], 4.0f, 4e-5f);
  // Through the perfect mirror: the albedo and normal of the wall it shows (facing the
  // reflected ray, -z), the depth of the mirror itself.
  expectPasses(image, mirror, {0.1f, 0.7f, 0.2f}, {0, 0, -1}, "the mirror");
  EXPECT_NEAR(image.depth[pixelOf(mirror)], 2.0f, 2e-5f);
  // A glTF material's albedo is its base colour; the normal the plane's.
  expectPasses(image, {0.0f, -0.8f, -3.0f}, {0.9f, 0.8f, 0.1f}, {0, 0.6f, 0.8f}, "the tilted plane");
  // The sky: its radiance as albedo, no normal, the documented far depth.
  expectPasses(image, sky, {0.3f, 0.6f, 0.9f}, {0, 0, 0}, "the sky");
  EXPECT_NEAR(image.depth[pixelOf(sky)], 1e10f, 1e5f);
}

TEST_P(Passes, TheFlagSelectsTheChannels) {
  const std::filesystem::path scene = passesScene();
  std::vector<std::string> flags = {"--width", "8", "--height", "8", "--spp", "1", "--passes", "normal,depth"};
  RadianceImage some = renderExr(GetParam(), scene, flags);
  EXPECT_TRUE(some.albedo.empty());
  EXPECT_EQ(some.normal.size(), 64u);
  EXPECT_EQ(some.depth.size(), 64u);
  flags.back() = "none";
  RadianceImage none = renderExr(GetParam(), scene, flags);
  EXPECT_TRUE(none.albedo.empty() && none.normal.empty() && none.depth.empty());
  EXPECT_EQ(none.variance.size(), 64u);
}

TEST(PassesFlag, ListPrintsTheChannelsAndABadNameIsAFlagError) {
  RunResult list = runWavepath({"render", "--passes", "list"});
  EXPECT_EQ(list.exitCode, 0) << list.err;
  for (const char* channel : {"albedo.R", "normal.X", "depth.Z"})
    EXPECT_NE(list.out.find(channel), std::string::npos) << list.out;
  RunResult bad = runWavepath({"render", (sourceDirectory() / "assets" / "cornell-box.gltf").string(), "--passes",
                               "albedo,speed"});
  EXPECT_EQ(bad.exitCode, 2) << bad.err;
  EXPECT_NE(bad.err.find("'speed' is not a feature pass"), std::string::npos) << bad.err;
}

INSTANTIATE_TEST_SUITE_P(Backend, Passes, ::testing::Values(std::string("vulkan"), std::string("opencl")),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace wp::test
