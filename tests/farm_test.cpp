// Long renders, end to end on both backends (lavapipe under validation, PoCL): a render
// killed with SIGKILL, or stopped by SIGTERM or SIGINT, and resumed from its checkpoint
// equals the uninterrupted render bit for bit; checkpoints of other renders or damaged ones
// are refused without being touched; --samples batches and --region crops merge into the
// whole render, and merge refuses parts that do not fit.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>
#include <thread>

#include "image/image_io.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

namespace fs = std::filesystem;

class Farm : public ::testing::TestWithParam<std::string> {
protected:
  void SetUp() override {
    dir = scratchDirectory("farm");
    checkpoint = dir / "render.wpck";
  }

  // 48x40 at 64 spp in passes of 512 paths: 240 passes, so a signal finds the render between
  // its first checkpoint and its end. --sky none, which the Cornell box has anyway, leaves the
  // lighting rule nothing to note, so a refusal is the only line.
  std::vector<std::string> renderArgs(const std::string& output, std::vector<std::string> extra = {},
                                      const std::string& spp = "") {
    std::vector<std::string> args = {"render", scene.string(), "-o", (dir / output).string(), "--backend", GetParam(),
                                     "--width", "48", "--height", "40", "--spp", spp.empty() ? samplesPerPixel : spp,
                                     "--max-paths", "512",
                                     "--sky", "none"};
    args.insert(args.end(), extraFlags.begin(), extraFlags.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }

  RadianceImage render(const std::string& output, const std::vector<std::string>& extra = {}) {
    RunResult r = runWavepath(renderArgs(output, extra));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    return readExr(dir / output);
  }

  // Starts a checkpointed render (a checkpoint after every pass) and sends `signal` once
  // its first checkpoint exists and `delay` more has passed.
  RunResult interruptedRender(int signal, std::chrono::milliseconds delay) {
    WavepathProcess p =
        startWavepath(renderArgs("out.exr", {"--checkpoint", checkpoint.string(), "--checkpoint-every", "0"}));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
    while (!fs::exists(checkpoint) && !p.ended() && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    std::this_thread::sleep_for(delay);
    ::kill(p.pid, signal);
    return waitWavepath(p);
  }

  // Resumes the render; checks that it started from a checkpoint part of the way through,
  // ended, and removed its checkpoint.
  RadianceImage resume() {
    RunResult r = runWavepath(renderArgs("out.exr", {"--checkpoint", checkpoint.string(), "--resume"}));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const size_t at = r.err.find("resuming from checkpoint");
    EXPECT_NE(at, std::string::npos) << r.err;
    if (at != std::string::npos) {
      const double sppDone = std::stod(r.err.substr(r.err.find(" at ", at) + 4));
      EXPECT_GT(sppDone, 0.0) << r.err;
      EXPECT_LT(sppDone, 64.0) << r.err;
    }
    EXPECT_FALSE(fs::exists(checkpoint)) << "the checkpoint outlived the finished render";
    return readExr(dir / "out.exr");
  }

  fs::path dir;
  fs::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  fs::path checkpoint;
  std::vector<std::string> extraFlags;  // every render of the test gets these
  std::string samplesPerPixel = "64";   // --spp of every render unless renderArgs is given one
};

// Radiance, variance and the feature passes (which must be there) the same bit for bit.
void expectBitIdentical(const RadianceImage& a, const RadianceImage& b) {
  ASSERT_EQ(a.mean.size(), b.mean.size());
  ASSERT_EQ(a.variance.size(), b.variance.size());
  ASSERT_EQ(a.albedo.size(), a.mean.size());
  ASSERT_EQ(a.normal.size(), a.mean.size());
  ASSERT_EQ(a.depth.size(), a.mean.size());
  ASSERT_EQ(b.albedo.size(), b.mean.size());
  ASSERT_EQ(b.normal.size(), b.mean.size());
  ASSERT_EQ(b.depth.size(), b.mean.size());
  for (size_t i = 0; i < a.mean.size(); ++i) {
    ASSERT_EQ(a.mean[i], b.mean[i]) << "pixel " << i;
    ASSERT_EQ(a.variance[i], b.variance[i]) << "pixel " << i;
    ASSERT_EQ(a.albedo[i], b.albedo[i]) << "pixel " << i;
    ASSERT_EQ(a.normal[i], b.normal[i]) << "pixel " << i;
    ASSERT_EQ(a.depth[i], b.depth[i]) << "pixel " << i;
  }
}

std::string fileBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeBytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

TEST_P(Farm, RenderKilledWithSigkillResumesBitIdentical) {
  RadianceImage uninterrupted = render("reference.exr");
  RunResult killed = interruptedRender(SIGKILL, std::chrono::milliseconds(150));
  ASSERT_EQ(killed.exitCode, -1) << "the render ended before the kill: " << killed.err;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  expectBitIdentical(resume(), uninterrupted);
}

TEST_P(Farm, SigtermWritesACheckpointExitsResumableAndTheResumeIsBitIdentical) {
  RadianceImage uninterrupted = render("reference.exr");
  RunResult stopped = interruptedRender(SIGTERM, std::chrono::milliseconds(0));
  EXPECT_EQ(stopped.exitCode, 75) << stopped.err;
  EXPECT_NE(stopped.err.find("run the same command with --resume"), std::string::npos) << stopped.err;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  expectBitIdentical(resume(), uninterrupted);
}

// Adaptive sampling keeps its state (each pixel's sample count and whether it stopped) in
// the accumulation, so a resumed adaptive render is the uninterrupted one bit for bit too.
// An 8x8 crop makes a pass of 512 paths 8 samples of every pixel, so the render is stopped
// at 8 samples or later, after the first check (at 4) has stopped some pixels: a resume that
// forgot them would give those pixels more samples. 1024 spp at most make 128 passes, so
// the signal finds the render still going.
TEST_P(Farm, AnAdaptiveRenderResumesBitIdentical) {
  extraFlags = {"--adaptive", "0.2", "--adaptive-min-samples", "4", "--region", "20,16,28,24"};
  samplesPerPixel = "1024";
  RadianceImage uninterrupted = render("reference.exr");
  ASSERT_FALSE(uninterrupted.sampleCount.empty());
  EXPECT_NE(std::count(uninterrupted.sampleCount.begin(), uninterrupted.sampleCount.end(), 4.0f), 0)
      << "no pixel stopped at the first check";
  RunResult stopped = interruptedRender(SIGTERM, std::chrono::milliseconds(0));
  EXPECT_EQ(stopped.exitCode, 75) << stopped.err;
  RadianceImage resumed = resume();
  expectBitIdentical(resumed, uninterrupted);
  EXPECT_EQ(resumed.sampleCount, uninterrupted.sampleCount);
}

TEST_P(Farm, SigintWithoutCheckpointWritesNothing) {
  WavepathProcess p = startWavepath(renderArgs("out.exr", {}, "4096"));
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  ::kill(p.pid, SIGINT);
  RunResult r = waitWavepath(p);
  EXPECT_EQ(r.exitCode, 128 + SIGINT) << r.err;
  EXPECT_NE(r.err.find("nothing written"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0) << "files left behind";
}

// Four batches of 16 samples merge into the 64-sample render. Each part's mean is its float
// sum over its samples divided by 16, the render's its float sum over all 64: sums of
// non-negative terms in another grouping, each within (n - 1) u ~ 64 * 6e-8 of the exact sum
// relatively, so means agree to 1e-5 relatively; the variance, which the render computes
// as (sum of squares - sum^2 / n) in float, agrees to a float rounding of the mean square.
TEST_P(Farm, FourSampleBatchesMergeIntoTheWholeRender) {
  RadianceImage whole = render("whole.exr");
  std::vector<std::string> merge = {"merge"};
  for (const char* batch : {"0..15", "16..31", "32..47", "48..63"}) {
    std::string name = std::string("batch") + batch + ".exr";
    RadianceImage part = render(name, {"--samples", batch});
    ASSERT_TRUE(part.record.has_value());
    EXPECT_EQ(part.record->sampleCount(), 16u);
    EXPECT_EQ(part.record->samplesPerPixel, 64u);
    EXPECT_EQ(part.record->sceneHash, whole.record->sceneHash);
    merge.push_back((dir / name).string());
  }
  merge.insert(merge.end(), {"-o", (dir / "merged.exr").string()});
  RunResult r = runWavepath(merge);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  RadianceImage merged = readExr(dir / "merged.exr");
  ASSERT_EQ(merged.mean.size(), whole.mean.size());
  double largestMean = 0.0, largestVariance = 0.0;
  size_t differing = 0;
  for (size_t i = 0; i < whole.mean.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double m = whole.mean[i][c], v = whole.variance[i][c];
      const double meanError = std::abs(merged.mean[i][c] - m), varianceError = std::abs(merged.variance[i][c] - v);
      EXPECT_LE(meanError, 1e-5 * m) << "pixel " << i << " channel " << c;
      EXPECT_LE(varianceError, 1e-4 * v + 1e-6 * (m * m + 64.0 * v) / 63.0) << "pixel " << i << " channel " << c;
      differing += merged.mean[i][c] != whole.mean[i][c];
      if (m > 0) largestMean = std::max(largestMean, meanError / m);
      largestVariance = std::max(largestVariance, varianceError / ((m * m + 64.0 * v) / 63.0));
    }
  }
  // The feature passes are means too, of terms at most 1 in size (albedo, normal) or
  // positive (depth): within 64 u of the sum of the terms' sizes.
  ASSERT_EQ(merged.albedo.size(), whole.albedo.size());
  ASSERT_EQ(merged.normal.size(), whole.normal.size());
  ASSERT_EQ(merged.depth.size(), whole.depth.size());
  ASSERT_FALSE(whole.depth.empty());
  for (size_t i = 0; i < whole.mean.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(merged.albedo[i][c], whole.albedo[i][c], 1e-5) << "pixel " << i << " channel " << c;
      EXPECT_NEAR(merged.normal[i][c], whole.normal[i][c], 1e-5) << "pixel " << i << " channel " << c;
    }
    EXPECT_NEAR(merged.depth[i], whole.depth[i], 1e-5 * whole.depth[i]) << "pixel " << i;
  }
  std::printf("merged 4 batches: %zu of %zu means differ, largest relative difference of a mean %.3g, largest difference of a variance %.3g of the mean square\n",
              differing, 3 * whole.mean.size(), largestMean, largestVariance);
  EXPECT_EQ(merged.record->firstSample, 0u);
  EXPECT_EQ(merged.record->lastSample, 63u);
}

// A pixel's samples do not depend on the crop that traces it, and merge copies a pixel held
// by one part as it is: crops merge into the whole render bit for bit, PNG byte for byte.
TEST_P(Farm, RegionsMergeIntoTheWholeRenderBitIdentical) {
  RadianceImage whole = render("whole.exr");
  RunResult png = runWavepath(renderArgs("whole.png"));
  ASSERT_EQ(png.exitCode, 0) << png.err;
  std::vector<std::string> crops = {"0,0,48,13", "0,13,20,40", "20,13,48,40"};
  std::vector<std::string> merge = {"merge"};
  for (size_t k = 0; k < crops.size(); ++k) {
    std::string name = "crop" + std::to_string(k) + ".exr";
    RadianceImage part = render(name, {"--region", crops[k]});
    EXPECT_EQ(part.width * part.height, k == 0 ? 48u * 13u : k == 1 ? 20u * 27u : 28u * 27u);
    merge.push_back((dir / name).string());
  }
  std::vector<std::string> toPng = merge;
  merge.insert(merge.end(), {"-o", (dir / "merged.exr").string()});
  toPng.insert(toPng.end(), {"-o", (dir / "merged.png").string()});
  ASSERT_EQ(runWavepath(merge).exitCode, 0);
  ASSERT_EQ(runWavepath(toPng).exitCode, 0);
  expectBitIdentical(readExr(dir / "merged.exr"), whole);
  EXPECT_EQ(fileBytes(dir / "merged.png"), fileBytes(dir / "whole.png"));
}

// The progress line as a user at a terminal sees it (script gives wavepath a pseudo-terminal),
// redrawn as passes end.
TEST(Progress, ATerminalShowsSamplesDoneRateAndTimeLeft) {
  const fs::path dir = scratchDirectory("progress");
  const fs::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  RunResult r = runShell("script -qefc \"'" + wavepathExecutable().string() + "' render '" + scene.string() + "' -o '" +
                         (dir / "out.exr").string() + "' --width 48 --height 40 --spp 64 --max-paths 512\" /dev/null");
  ASSERT_EQ(r.exitCode, 0) << r.out;
  const std::regex line(R"(\[[#.]{30}\] (\d+\.\d) of 64 spp \(\d+\.\d%\), \d+\.\d\d M samples/s, \d+:\d\d spent, \d+:\d\d left)");
  std::vector<double> done;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), line); it != std::sregex_iterator(); ++it)
    done.push_back(std::stod((*it)[1]));
  ASSERT_GE(done.size(), 2u) << "expected the line redrawn in: " << r.out;
  EXPECT_TRUE(std::is_sorted(done.begin(), done.end()));
  EXPECT_GT(done.back(), done.front());
}

const auto kBackends = ::testing::Values(std::string("vulkan"), std::string("opencl"));
INSTANTIATE_TEST_SUITE_P(Backend, Farm, kBackends,
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

class FarmRefusals : public Farm {};

TEST_P(FarmRefusals, CheckpointsOfOtherRendersAndDamagedOnesAreRefusedUntouched) {
  ASSERT_EQ(interruptedRender(SIGTERM, std::chrono::milliseconds(0)).exitCode, 75);
  const std::string saved = fileBytes(checkpoint);
  auto resumeWith = [&](const std::vector<std::string>& extra, const fs::path& scenePath) {
    std::vector<std::string> args = renderArgs("out.exr", {"--checkpoint", checkpoint.string(), "--resume"});
    args[1] = scenePath.string();
    args.insert(args.end(), extra.begin(), extra.end());
    return runWavepath(args);
  };
  expectOneErrorLine(resumeWith({"--max-depth", "3"}, scene), "--max-depth is 8 there, 3 here", 1);
  expectOneErrorLine(resumeWith({"--fstop", "8", "--focus-distance", "3"}, scene),
                     "the scene, camera or sky differs", 1);
  // The Cornell box with one wall's colour changed.
  std::string otherScene = fileBytes(scene);
  otherScene.replace(otherScene.find("0.885809"), 8, "0.785809");
  writeBytes(dir / "other.gltf", otherScene);
  expectOneErrorLine(resumeWith({}, dir / "other.gltf"), "the scene, camera or sky differs", 1);
  EXPECT_EQ(fileBytes(checkpoint), saved);

  writeBytes(checkpoint, saved.substr(0, saved.size() / 2));
  expectOneErrorLine(resumeWith({}, scene), "truncated or damaged", 1);
  std::string flipped = saved;
  flipped[flipped.size() / 2] ^= 0x10;
  writeBytes(checkpoint, flipped);
  expectOneErrorLine(resumeWith({}, scene), "truncated or damaged", 1);
  EXPECT_EQ(fileBytes(checkpoint), flipped);
  writeBytes(checkpoint, "P3\n1 1\n255\n0 0 0\n");
  expectOneErrorLine(resumeWith({}, scene), "not a wavepath checkpoint", 1);
  EXPECT_FALSE(fs::exists(dir / "out.exr"));

  // Without --resume a checkpoint in the way is refused; --resume needs one.
  RunResult clobber = runWavepath(renderArgs("out.exr", {"--checkpoint", checkpoint.string()}));
  expectOneErrorLine(clobber, "add --resume", 2);
  RunResult missing = runWavepath(renderArgs("out.exr", {"--checkpoint", (dir / "none.wpck").string(), "--resume"}));
  expectOneErrorLine(missing, "does not exist", 2);
  RunResult same = runWavepath(renderArgs("out.exr", {"--checkpoint", (dir / "out.exr").string()}));
  expectOneErrorLine(same, "is the output image too", 2);
}

TEST_P(FarmRefusals, MergeRefusesOverlapsGapsAndPartsOfAnotherFrame) {
  for (const char* batch : {"0..31", "32..63", "16..47"}) render(std::string("b") + batch + ".exr", {"--samples", batch});
  render("seed.exr", {"--samples", "32..63", "--seed", "5"});
  auto merge = [&](const std::vector<std::string>& parts) {
    std::vector<std::string> args = {"merge"};
    for (const std::string& p : parts) args.push_back((dir / p).string());
    args.insert(args.end(), {"-o", (dir / "merged.exr").string()});
    return runWavepath(args);
  };
  expectOneErrorLine(merge({"b0..31.exr", "b16..47.exr"}), "hold the same samples", 1);
  expectOneErrorLine(merge({"b0..31.exr"}), "has 32 of its 64 samples", 1);
  expectOneErrorLine(merge({"b0..31.exr", "seed.exr"}), "--seed is 5 there, 0 here", 1);
  EXPECT_FALSE(fs::exists(dir / "merged.exr"));
  ASSERT_EQ(merge({"b0..31.exr", "b32..63.exr"}).exitCode, 0) << "the control case";

  expectOneErrorLine(runWavepath(renderArgs("x.exr", {"--samples", "60..64"})), "goes past the 64 samples", 2);
  expectOneErrorLine(runWavepath(renderArgs("x.exr", {"--region", "0,0,49,40"})), "is not a crop of the 48x40", 2);
  expectOneErrorLine(runWavepath(renderArgs("x.exr", {"--region", "0,0,10"})), "X0,Y0,X1,Y1", 2);
}

INSTANTIATE_TEST_SUITE_P(Backend, FarmRefusals, ::testing::Values(std::string("vulkan")),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace wp::test
