// Depth of field end to end: an edge at the focus distance stays sharp, one off focus blurs by
// the circle of confusion the thin-lens equation predicts.
#include <gtest/gtest.h>

#include <cmath>

#include "image/image_io.h"
#include "shaders/common/thin_lens.h"
#include "support/gltf_writer.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

constexpr int kWidth = 240;
constexpr int kHeight = 120;

// A black quad (albedo 0, so it shows as 0 against the white sky of a scene without
// emitters) spanning x in [-20, 0] at depth `depth`, above (upper) or below y = 0.
TestMesh blackQuad(float depth, bool upper) {
  float y0 = upper ? 0.0f : -20.0f, y1 = upper ? 20.0f : 0.0f;
  TestMesh quad;
  quad.positions = {{-20.0f, y0, -depth}, {0.0f, y0, -depth}, {0.0f, y1, -depth}, {-20.0f, y1, -depth}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  return quad;
}

// Standard deviation, in pixels, of the edge's line spread function (the derivative along x
// of the rows' mean profile, which rises from 0 behind the quad to 1 on the sky).
double edgeSpread(const RadianceImage& image, int firstRow, int lastRow) {
  std::vector<double> profile(image.width, 0.0);
  for (int y = firstRow; y <= lastRow; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      profile[x] += image.mean[y * image.width + x].x / double(lastRow - firstRow + 1);
    }
  }
  double total = 0.0, mean = 0.0, second = 0.0;
  for (uint32_t x = 1; x < image.width; ++x) {
    double weight = profile[x] - profile[x - 1];
    double position = double(x);  // between pixel centres x - 1 and x
    total += weight;
    mean += weight * position;
    second += weight * position * position;
  }
  mean /= total;
  return std::sqrt(second / total - mean * mean);
}

TEST(DepthOfField, EdgeAtFocusStaysSharpAndOffFocusBlursByTheCircleOfConfusion) {
  const float focus = 2.0f, nearDepth = 1.0f, fStop = 1.4f, yfov = 0.25f;
  TestScene scene;
  scene.materials.push_back({glm::vec3(0.0f), glm::vec3(0.0f), false});
  scene.meshes = {blackQuad(focus, true), blackQuad(nearDepth, false)};
  scene.camera.yfovRadians = yfov;
  std::filesystem::path dir = scratchDirectory("dof");
  std::filesystem::path file = writeGltf(scene, dir / "edges.gltf");
  std::filesystem::path out = dir / "edges.exr";
  RunResult r = runWavepath({"render", file.string(), "-o", out.string(), "--width", std::to_string(kWidth),
                             "--height", std::to_string(kHeight), "--spp", "128", "--fstop", std::to_string(fStop),
                             "--focus-distance", std::to_string(focus)});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  RadianceImage image = readExr(out);

  // The lens wavepath builds for this camera (src/render/camera_lens.cpp): the film crop of a
  // 2:1 image on the 36x24 mm sensor, and the focal length that sees yfov at the focus.
  glm::vec2 filmHalf = gpu::filmHalfExtent({WP_SENSOR_WIDTH, WP_SENSOR_HEIGHT}, float(kWidth) / kHeight);
  float filmDistance = gpu::focalLengthForFieldOfView(yfov, filmHalf.y);
  float focalLength = filmDistance * focus / (filmDistance + focus);
  float coc = gpu::circleOfConfusion(focalLength / fStop, focalLength, focus, nearDepth);
  double cocPixels = coc / (2.0 * filmHalf.y) * kHeight;
  ASSERT_GT(cocPixels, 8.0) << "the set-up must blur enough to measure";

  // A pixel-wide box filter alone spreads an edge by sqrt(1/12) pixel; a uniform disk of
  // diameter c adds a spread of c / 4.
  double sharp = edgeSpread(image, 5, kHeight / 2 - 15);
  double blurred = edgeSpread(image, kHeight / 2 + 15, kHeight - 5);
  double expected = std::sqrt(cocPixels * cocPixels / 16.0 + 1.0 / 12.0);
  EXPECT_LT(sharp, 0.5) << "the edge in focus blurred";
  // 5%: the measured spread carries sample noise and the discrete derivative's error.
  EXPECT_NEAR(blurred, expected, 0.05 * expected) << "circle of confusion " << cocPixels << " px";
}

}  // namespace
}  // namespace wp::test
