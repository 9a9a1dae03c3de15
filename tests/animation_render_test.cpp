// End to end: `wavepath render --frames` writes an image sequence in which moved objects move,
// and updating a pose gives what packing it from scratch gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

// The pixel (column, row from the top) that sees world point (x, y, 0) from the camera of
// tests/data/anim_trs.gltf: at (0, 0, 5) looking down -z, yfov 0.8, a square image.
std::pair<uint32_t, uint32_t> pixelOf(float x, float y, uint32_t size) {
  const float halfHeight = 5.0f * std::tan(0.4f);
  const float u = (x / halfHeight + 1.0f) / 2.0f;
  const float v = (1.0f - y / halfHeight) / 2.0f;
  return {uint32_t(u * float(size)), uint32_t(v * float(size))};
}

TEST(AnimationSequence, FramesAreWrittenAndTheMovingTriangleMoves) {
  const std::filesystem::path dir = scratchDirectory("sequence");
  const std::filesystem::path scene = sourceDirectory() / "tests" / "data" / "anim_trs.gltf";
  const uint32_t size = 32;
  // Frames 0, 1, 2 at 2 fps: 0, 0.5 and 1 s.
  const RunResult r = runWavepath({"render", scene.string(), "-o", (dir / "frame_##.exr").string(), "--frames",
                                   "0..2", "--fps", "2", "--width", "32", "--height", "32", "--spp", "4"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
  for (const char* name : {"frame_00.exr", "frame_01.exr", "frame_02.exr"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  }
  // The triangle (0,0,0), (1,0,0), (0,1,0) of node "mover" moves by 2 in x over 1 s, so at
  // 0.5 s it covers the point (1.33, 0.33, 0), where at 0 s nothing was but the white sky.
  const RadianceImage before = readExr(dir / "frame_00.exr");
  const RadianceImage after = readExr(dir / "frame_01.exr");
  const auto [column, row] = pixelOf(4.0f / 3.0f, 1.0f / 3.0f, size);
  const size_t pixel = size_t(row) * size + column;
  // The sky is radiance 1 exactly (the camera ray escapes at once); the triangle is Lambertian
  // with albedo 0.2 under that sky, so it reflects at most 0.2.
  EXPECT_NEAR(before.mean[pixel].g, 1.0f, 1e-5f);
  EXPECT_LT(after.mean[pixel].g, 0.25f);
}

// A sequence packs its first pose and then updates it (refits deformed meshes' BVHs, rebuilds
// the top level); a single --time render packs that pose from scratch. Both hold the same
// triangles, so every ray hits the same surface at the same distance and, with the same seed,
// the images are identical bit for bit: any difference means the update lost or misplaced
// geometry, a light or a transform. The demo scene has a skinned bar, a morphing sphere and
// a moving cube, so all three kinds of update are covered.
TEST(AnimationSequence, UpdatedPosesRenderAsPosesPackedFromScratch) {
  const std::filesystem::path dir = scratchDirectory("sequence-update");
  const std::filesystem::path scene = sourceDirectory() / "assets" / "animated.gltf";
  const std::vector<std::string> common = {"--width", "40", "--height", "40", "--spp", "4", "--seed", "3"};
  auto render = [&](std::vector<std::string> args) {
    args.insert(args.begin(), {"render", scene.string()});
    args.insert(args.end(), common.begin(), common.end());
    const RunResult r = runWavepath(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
  };
  render({"-o", (dir / "frame_#.exr").string(), "--frames", "0..3", "--fps", "4"});
  render({"-o", (dir / "single.exr").string(), "--time", "0.75"});
  const RadianceImage sequence = readExr(dir / "frame_3.exr");
  const RadianceImage single = readExr(dir / "single.exr");
  ASSERT_EQ(sequence.mean.size(), single.mean.size());
  size_t differing = 0;
  for (size_t i = 0; i < single.mean.size(); ++i) {
    differing += sequence.mean[i] != single.mean[i];
  }
  EXPECT_EQ(differing, 0u);
  const RadianceImage first = readExr(dir / "frame_0.exr");
  EXPECT_NE(first.mean, single.mean);  // the poses differ, so the comparison means something
}

// Per-pixel z of two renders' difference in the green channel, over the pixels with noise in
// either (the open sky is exactly 1 in both): its mean square is 1 when they estimate the same
// image, and grows with any systematic difference. A noiseless pixel that differs fails.
double meanSquaredZ(const RadianceImage& a, const RadianceImage& b) {
  double sum = 0.0;
  size_t noisy = 0;
  for (size_t i = 0; i < a.mean.size(); ++i) {
    const double variance = double(a.variance[i].g) + double(b.variance[i].g);
    const double difference = double(a.mean[i].g) - double(b.mean[i].g);
    if (variance > 0.0) {
      sum += difference * difference / variance;
      ++noisy;
    } else if (std::abs(difference) > 1e-6) {
      return 1e6;
    }
  }
  return noisy ? sum / double(noisy) : 0.0;
}

// glTF animation through the shutter: with the camera's shutter open for 0.25 s at 0.5 s,
// the render sees the mover slide, the spinner turn and the sphere grow, and equals the
// average of renders at 16 instants spread over that interval. The slide and the turn are
// exactly what the two-key motion interpolates (LINEAR translation, slerp); the sphere's
// CUBICSPLINE scale is not linear in time, but over a quarter second it bends by less than
// 1% of its radius, well below the noise of this comparison.
TEST(AnimationSequence, AnOpenShutterAveragesTheInstantsItSpans) {
  const std::filesystem::path dir = scratchDirectory("shutter");
  const std::filesystem::path scene = sourceDirectory() / "tests" / "data" / "anim_trs.gltf";
  auto render = [&](const std::string& name, double time, double shutter, uint32_t spp, uint32_t seed) {
    std::vector<std::string> args = {"render", scene.string(), "-o", (dir / name).string(), "--time",
                                     std::to_string(time), "--width", "32", "--height", "32", "--spp",
                                     std::to_string(spp), "--seed", std::to_string(seed)};
    if (shutter > 0.0) args.insert(args.end(), {"--shutter", std::to_string(shutter)});
    const RunResult r = runWavepath(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return readExr(dir / name);
  };
  const RadianceImage blurred = render("blurred.exr", 0.5, 0.25, 256, 1);
  constexpr int kInstants = 16;
  RadianceImage average = blurred;
  std::fill(average.mean.begin(), average.mean.end(), glm::vec3(0.0f));
  std::fill(average.variance.begin(), average.variance.end(), glm::vec3(0.0f));
  for (int k = 0; k < kInstants; ++k) {
    const RadianceImage instant = render("instant.exr", 0.5 + 0.25 * (k + 0.5) / kInstants, 0.0, 16, 2 + k);
    for (size_t i = 0; i < average.mean.size(); ++i) {
      average.mean[i] += instant.mean[i] / float(kInstants);
      average.variance[i] += instant.variance[i] / float(kInstants * kInstants);
    }
  }
  const RadianceImage still = render("still.exr", 0.5, 0.0, 256, 1);
  // Independent estimates of one image: mean z^2 = 1 up to noise (hundreds of pixels) and to
  // the variance estimates of pixels whose paths rarely see an edge; 2 leaves room for both.
  EXPECT_LT(meanSquaredZ(blurred, average), 2.0);  // measured 1.17
  // The same comparison against the scene frozen at shutter open fails: the blur is real.
  EXPECT_GT(meanSquaredZ(blurred, still), 10.0);  // measured 108
}

}  // namespace
}  // namespace wp::test
