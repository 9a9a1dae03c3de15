// The pieces of long renders without a device: the progress line, the checkpoint file
// (round trip, damage detected), and the merge of parts against the statistics of all
// their samples taken together.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "core/error.h"
#include "render/checkpoint.h"
#include "render/part_merge.h"
#include "render/render_progress.h"
#include "support/run_wavepath.h"

namespace wp {
namespace {

TEST(ProgressLine, SaysSamplesDoneRateAndTimeLeft) {
  // 100 pixels, 640 of 6400 samples done in 2 s of which 320 by this process: 160 samples/s,
  // 5760 left take 36 s.
  RenderProgress p{100, 640, 6400, 320, 2.0};
  EXPECT_EQ(progressLine(p), "6.4 of 64 spp (10.0%), 0.00 M samples/s, 0:02 spent, 0:36 left");
  RenderProgress hours{1000, 1000000, 9000000, 1000000, 1000.0};
  EXPECT_EQ(progressLine(hours), "1000.0 of 9000 spp (11.1%), 0.00 M samples/s, 16:40 spent, 2:13:20 left");
  EXPECT_NE(progressLine({100, 0, 6400, 0, 0.0}).find("? left"), std::string::npos);
}

TEST(ProgressLine, WithATimeLimitThatComesFirstSaysTheTimeLeft) {
  // At 160 samples/s the 5760 samples left take 36 s, past a limit of 10 s: 8 s are left.
  RenderProgress p{100, 640, 6400, 320, 2.0, 10.0};
  EXPECT_EQ(progressLine(p), "6.4 spp (20.0% of the time limit), 0.00 M samples/s, 0:02 spent, 0:08 left");
  EXPECT_DOUBLE_EQ(progressFraction(p), 0.2) << "the bar follows the time";
  // Before anything was measured the limit is all that is known.
  EXPECT_EQ(progressLine({100, 0, 6400, 0, 0.0, 10.0}),
            "0.0 spp (0.0% of the time limit), 0.00 M samples/s, 0:00 spent, 0:10 left");
  // Samples that end the render first keep the samples' line.
  p.timeLimitSeconds = 60.0;
  EXPECT_EQ(progressLine(p), "6.4 of 64 spp (10.0%), 0.00 M samples/s, 0:02 spent, 0:36 left");
  EXPECT_DOUBLE_EQ(progressFraction(p), 0.1);
}

Checkpoint smallCheckpoint() {
  Checkpoint c;
  c.identity = {"0123456789abcdef", "--width 3 --height 2 --seed 1"};
  c.samplesPerPixel = 16;
  c.firstSample = 4;
  c.endSample = 12;
  c.region = {1, 0, 3, 2};
  c.pathsDone = 4 * 4 + 3;
  c.device = "vulkan: test device";
  for (int i = 0; i < 4; ++i) {
    c.accumulation.sum.push_back(glm::vec4(0.1f * i, 1e-30f, 3.0e30f, 0.0f));
    c.accumulation.sumSquares.push_back(glm::vec4(std::nextafter(1.0f, 2.0f), 0.0f, 7.0f * i, 0.0f));
    c.accumulation.albedoDepth.push_back(glm::vec4(0.25f * i, 0.5f, 1.0f / 3.0f, 1e10f + 3.0f * i));
    c.accumulation.normal.push_back(glm::vec4(-0.5f * i, 1e-20f, std::nextafter(-1.0f, 0.0f), 0.0f));
  }
  return c;
}

TEST(CheckpointFile, RoundTripsEveryBit) {
  std::filesystem::path file = test::scratchDirectory("checkpoint") / "c.wpck";
  Checkpoint c = smallCheckpoint();
  writeCheckpoint(file, c);
  Checkpoint r = readCheckpoint(file);
  EXPECT_EQ(r.identity.sceneHash, c.identity.sceneHash);
  EXPECT_EQ(r.identity.settings, c.identity.settings);
  EXPECT_EQ(r.samplesPerPixel, 16u);
  EXPECT_EQ(r.firstSample, 4u);
  EXPECT_EQ(r.endSample, 12u);
  EXPECT_TRUE(r.region == c.region);
  EXPECT_EQ(r.pathsDone, c.pathsDone);
  EXPECT_EQ(r.device, c.device);
  EXPECT_EQ(r.accumulation.sum, c.accumulation.sum);
  EXPECT_EQ(r.accumulation.sumSquares, c.accumulation.sumSquares);
  EXPECT_EQ(r.accumulation.albedoDepth, c.accumulation.albedoDepth);
  EXPECT_EQ(r.accumulation.normal, c.accumulation.normal);
}

TEST(CheckpointFile, EveryTruncationAndEveryFlippedByteIsRefused) {
  std::filesystem::path dir = test::scratchDirectory("checkpoint-damage");
  writeCheckpoint(dir / "c.wpck", smallCheckpoint());
  std::ifstream in(dir / "c.wpck", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto refused = [&](const std::string& damaged) {
    std::ofstream(dir / "d.wpck", std::ios::binary | std::ios::trunc) << damaged;
    try {
      readCheckpoint(dir / "d.wpck");
    } catch (const Error&) {
      return true;
    }
    return false;
  };
  for (size_t length = 0; length < bytes.size(); ++length) EXPECT_TRUE(refused(bytes.substr(0, length))) << length;
  for (size_t at = 0; at < bytes.size(); ++at) {
    std::string flipped = bytes;
    flipped[at] ^= 0x01;
    EXPECT_TRUE(refused(flipped)) << "byte " << at;
  }
  EXPECT_FALSE(refused(bytes)) << "the control case";
}

// A part of `samples` samples per pixel as the renderer writes it: the mean and the
// variance of the mean (the unbiased sample variance over n), and feature passes that are
// means of the samples too (albedo the samples, normal their negative, depth their x).
FramePart makePart(const std::vector<std::vector<glm::dvec3>>& samples, uint32_t first, uint32_t count,
                   uint32_t width, uint32_t height, uint32_t spp) {
  FramePart part;
  part.name = std::to_string(first);
  part.image.width = width;
  part.image.height = height;
  RenderRecord r;
  r.frameWidth = width;
  r.frameHeight = height;
  r.samplesPerPixel = spp;
  r.firstSample = first;
  r.lastSample = first + count - 1;
  r.x1 = width;
  r.y1 = height;
  part.image.record = r;
  for (const std::vector<glm::dvec3>& pixel : samples) {
    glm::dvec3 mean(0.0), m2(0.0);
    for (uint32_t k = first; k < first + count; ++k) mean += pixel[k] / double(count);
    for (uint32_t k = first; k < first + count; ++k) m2 += (pixel[k] - mean) * (pixel[k] - mean);
    part.image.mean.push_back(glm::vec3(mean));
    part.image.variance.push_back(count > 1 ? glm::vec3(m2 / double(count - 1) / double(count)) : glm::vec3(0.0f));
    part.image.albedo.push_back(glm::vec3(mean));
    part.image.normal.push_back(glm::vec3(-mean));
    part.image.depth.push_back(float(mean.x));
  }
  return part;
}

// Batches of unequal sizes merge into the mean and variance of the mean over all samples,
// and the feature passes into their means over all samples, computed directly in double:
// to float rounding of the parts' values (2e-6 relative).
TEST(MergeParts, BatchesGiveTheMeanAndVarianceOfAllSamples) {
  const uint32_t width = 5, height = 3, spp = 40;
  std::mt19937 rng(7);
  std::exponential_distribution<double> radiance(2.0);
  std::vector<std::vector<glm::dvec3>> samples(width * height);
  for (auto& pixel : samples)
    for (uint32_t k = 0; k < spp; ++k) pixel.push_back(glm::dvec3(radiance(rng), radiance(rng), 3.0 + radiance(rng)));
  std::vector<FramePart> parts = {makePart(samples, 25, 15, width, height, spp), makePart(samples, 0, 1, width, height, spp),
                                  makePart(samples, 1, 24, width, height, spp)};
  RadianceImage merged = mergeParts(parts);
  FramePart all = makePart(samples, 0, spp, width, height, spp);
  for (size_t i = 0; i < samples.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(merged.mean[i][c], all.image.mean[i][c], 2e-6 * all.image.mean[i][c]) << i;
      EXPECT_NEAR(merged.variance[i][c], all.image.variance[i][c], 2e-5 * all.image.variance[i][c]) << i;
      EXPECT_NEAR(merged.albedo[i][c], all.image.albedo[i][c], 2e-6 * all.image.albedo[i][c]) << i;
      EXPECT_NEAR(merged.normal[i][c], all.image.normal[i][c], 2e-6 * -all.image.normal[i][c]) << i;
    }
    EXPECT_NEAR(merged.depth[i], all.image.depth[i], 2e-6 * all.image.depth[i]) << i;
  }
  EXPECT_EQ(merged.record->firstSample, 0u);
  EXPECT_EQ(merged.record->lastSample, spp - 1);
}

}  // namespace
}  // namespace wp
