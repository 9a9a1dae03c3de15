// --time-limit: a render that ends once its time is up, with whole samples in every pixel,
// and an image equal bit for bit to a render of that many samples (the samples a pixel gets
// do not depend on how the render is cut into passes); on both backends (lavapipe under
// validation, PoCL). The time a render takes is never asserted, only what it holds.
#include <gtest/gtest.h>

#include <regex>

#include "app/command_line.h"
#include "image/image_io.h"
#include "render/settings.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

namespace fs = std::filesystem;

// The samples per pixel the render command would render with these flags after the scene.
uint32_t sppParsedFrom(std::vector<std::string> flags) {
  std::vector<std::string> words = {"wavepath", "render", "scene.gltf"};
  words.insert(words.end(), flags.begin(), flags.end());
  std::vector<const char*> argv;
  for (const std::string& w : words) argv.push_back(w.c_str());
  CommandLine line;
  EXPECT_FALSE(parseCommandLine(line, int(argv.size()), argv.data()).has_value());
  return line.renderOptions.settings.samplesPerPixel;
}

TEST(TimeLimitFlag, WithoutSppTheTimeIsTheOnlyLimit) {
  EXPECT_EQ(sppParsedFrom({"--time-limit", "60"}), kMaxSamplesPerPixel);
  EXPECT_EQ(sppParsedFrom({"--time-limit", "60", "--spp", "7"}), 7u);
  EXPECT_EQ(sppParsedFrom({"--spp", "7", "--time-limit", "60"}), 7u);
  EXPECT_EQ(sppParsedFrom({}), RenderSettings{}.samplesPerPixel);
}

class TimeLimit : public ::testing::TestWithParam<std::string> {
protected:
  // The Cornell box at 48x40 in passes of 512 paths (3.75 samples per pixel), so a pass
  // ends mid-sample and the render must go on to finish it.
  // A time limit that does not end the render fails by runWavepath's timeout.
  RunResult render(const std::string& output, std::vector<std::string> extra, int timeoutSeconds = 120) {
    std::vector<std::string> args = {"render", scene.string(), "-o", (dir / output).string(), "--backend", GetParam(),
                                     "--width", "48", "--height", "40", "--max-paths", "512", "--sky", "none"};
    args.insert(args.end(), extra.begin(), extra.end());
    RunResult r = runWavepath(args, {}, timeoutSeconds);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    return r;
  }

  // Renders with the time limit, then with --spp set to the samples the first one ended
  // at, and expects the two images bit for bit the same; returns that sample count.
  uint32_t expectTheImageOfItsSamples(const std::vector<std::string>& flags, const std::string& limit,
                                      uint32_t mostSamples) {
    std::vector<std::string> timed = flags;
    timed.insert(timed.end(), {"--time-limit", limit, "--spp", std::to_string(mostSamples)});
    RunResult r = render("timed.exr", timed);
    const RadianceImage image = readExr(dir / "timed.exr");
    if (!image.record) {
      ADD_FAILURE() << "the EXR has no render record";
      return 0;
    }
    const uint32_t samples = image.record->samplesPerPixel;
    EXPECT_GE(samples, 1u);
    EXPECT_LE(samples, mostSamples);
    EXPECT_EQ(image.record->firstSample, 0u);
    EXPECT_EQ(image.record->lastSample, samples - 1) << "the record must say what the image holds";
    std::smatch summary;
    EXPECT_TRUE(std::regex_search(r.out, summary, std::regex(R"(48x40, (\d+) spp in ([0-9.]+) s)"))) << r.out;
    if (!summary.empty()) {
      EXPECT_EQ(std::stoul(summary[1].str()), samples) << r.out;
      if (samples < mostSamples) {
        EXPECT_GE(std::stod(summary[2].str()), std::stod(limit)) << "ended before its time was up: " << r.out;
        EXPECT_NE(r.err.find("the time limit (" + limit + " s) ended the render at " + std::to_string(samples) +
                             " spp"),
                  std::string::npos)
            << r.err;
      }
    }

    std::vector<std::string> fixed = flags;
    fixed.insert(fixed.end(), {"--spp", std::to_string(samples)});
    render("fixed.exr", fixed);
    const RadianceImage same = readExr(dir / "fixed.exr");
    EXPECT_EQ(same.record ? same.record->samplesPerPixel : 0u, samples);
    EXPECT_EQ(image.mean.size(), same.mean.size());
    EXPECT_EQ(image.variance.size(), same.variance.size());
    for (size_t i = 0; i < image.mean.size() && i < same.mean.size(); ++i) {
      EXPECT_EQ(image.mean[i], same.mean[i]) << "pixel " << i;
      EXPECT_EQ(image.variance[i], same.variance[i]) << "pixel " << i;
      if (image.mean[i] != same.mean[i] || image.variance[i] != same.variance[i]) break;
    }
    return samples;
  }

  fs::path dir = scratchDirectory("time-limit");
  fs::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
};

TEST_P(TimeLimit, EndsWithWholeSamplesAndTheImageOfThatMany) {
  const uint32_t samples = expectTheImageOfItsSamples({}, "0.5", 1u << 20);
  EXPECT_LT(samples, 1u << 20) << "the limit never ended the render";
}

TEST_P(TimeLimit, WithAdaptiveSamplingEndsWithTheSamplesItHadDecided) {
  const uint32_t samples =
      expectTheImageOfItsSamples({"--adaptive", "0.05", "--adaptive-min-samples", "2"}, "0.5", 1u << 20);
  EXPECT_LT(samples, 1u << 20) << "the limit never ended the render";
}

TEST_P(TimeLimit, ALimitTheRenderDoesNotReachChangesNothing) {
  EXPECT_EQ(expectTheImageOfItsSamples({}, "1000", 4), 4u);
}

INSTANTIATE_TEST_SUITE_P(Backend, TimeLimit, ::testing::Values(std::string("vulkan"), std::string("opencl")),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(TimeLimitRefusals, AreOneErrorLine) {
  const fs::path dir = scratchDirectory("time-limit-refusals");
  const std::string scene = (sourceDirectory() / "assets" / "cornell-box.gltf").string();
  auto run = [&](std::vector<std::string> extra, std::vector<std::string> env = {}) {
    std::vector<std::string> args = {"render", scene, "-o", (dir / "x.exr").string(), "--width", "48", "--height",
                                     "40", "--sky", "none", "--backend", "vulkan"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runWavepath(args, env);
  };
  expectOneErrorLine(run({"--time-limit", "0"}), "'0' must be more than 0", 2);
  expectOneErrorLine(run({"--time-limit", "-3"}), "'-3' must be more than 0", 2);
  expectOneErrorLine(run({"--time-limit", "1", "--samples", "0..3"}), "excludes", 2);
  expectOneErrorLine(run({"--time-limit", "1", "--checkpoint", (dir / "c.wpck").string()}), "excludes", 2);
  // An image in tiles renders each tile to the end before the next: a limit would leave the
  // last ones black. 16 KiB of buffer hold 256 pixels' sums (device_limits_test.cpp).
  expectOneErrorLine(run({"--time-limit", "1"}, {"WAVEPATH_MAX_BUFFER_BYTES=16384"}),
                     "which a time limit would leave unfinished");
  EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

}  // namespace
}  // namespace wp::test
