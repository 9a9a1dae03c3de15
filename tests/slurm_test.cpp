// The Slurm recipe end to end: a single-node cluster on localhost started by the test
// (tools/slurm/local-cluster: munged, slurmctld and slurmd with their own pid files, stopped
// by those pids whatever happens), then tools/slurm/submit's jobs: the 4-task array of
// Cornell-box sample batches and its dependent merge job, checked against one render of all
// the samples; and an array over an animation's frames, checked against a sequence render.
// A machine where the daemons cannot start fails, saying why.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "image/image_io.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

class Slurm : public ::testing::Test {
protected:
  void SetUp() override {
    dir = scratchDirectory("slurm");
    cluster = dir / "cluster";
    // The cluster also stops when this test process ends, killed or not.
    RunResult start = runShell(script("local-cluster") + " start " + quoted(cluster) + " " + std::to_string(::getpid()));
    ASSERT_EQ(start.exitCode, 0) << "no Slurm cluster on this machine:\n" << start.out;
  }
  void TearDown() override { runShell(script("local-cluster") + " stop " + quoted(cluster)); }

  std::string script(const std::string& name) { return quoted(sourceDirectory() / "tools" / "slurm" / name); }

  // Runs tools/slurm/submit with `arguments` on the cluster (the jobs inherit this
  // environment: validation on, the test run's OpenCL cache) and waits up to 150 s for the
  // job whose id follows `jobLabel` in its output to complete.
  void submitAndWait(const std::string& arguments, const std::string& jobLabel, const fs::path& logs) {
    RunResult submit = runShell("env SLURM_CONF=" + quoted(cluster / "slurm.conf") +
                                " WAVEPATH_VALIDATION=1 WAVEPATH_CACHE_DIR='" WAVEPATH_TEST_CACHE_DIR "' " +
                                script("submit") + " --wavepath " + quoted(wavepathExecutable()) + " " + arguments);
    ASSERT_EQ(submit.exitCode, 0) << submit.out;
    const size_t at = submit.out.find(jobLabel);
    ASSERT_NE(at, std::string::npos) << submit.out;
    const size_t from = at + jobLabel.size();
    const std::string job = submit.out.substr(from, submit.out.find('\n', from) - from);
    std::string state;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(150);
    while ((state = jobState(job)) != "COMPLETED" && std::chrono::steady_clock::now() < deadline) {
      ASSERT_TRUE(state == "PENDING" || state == "RUNNING" || state == "CONFIGURING" || state == "COMPLETING")
          << "job " << job << " is " << state << "\n"
          << runShell("tail -n 5 " + quoted(logs) + "/*.log").out;
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
    }
    ASSERT_EQ(state, "COMPLETED") << "job " << job << " did not complete in 150 s\n"
                                  << runShell("env SLURM_CONF=" + quoted(cluster / "slurm.conf") + " squeue").out;
  }

  // The job's state (PENDING, RUNNING, COMPLETED, FAILED, ...) as scontrol reports it; for
  // an array, the first of its tasks' states that is not COMPLETED, else COMPLETED.
  std::string jobState(const std::string& id) {
    std::string out = runShell("env SLURM_CONF=" + quoted(cluster / "slurm.conf") + " scontrol show job -o " + id).out;
    std::string state = "unknown (" + out + ")";
    for (size_t at = out.find("JobState="); at != std::string::npos; at = out.find("JobState=", at + 1)) {
      state = out.substr(at + 9, out.find(' ', at) - at - 9);
      if (state != "COMPLETED") break;
    }
    return state;
  }

  fs::path dir, cluster;
};

TEST_F(Slurm, FourTaskArrayAndMergeJobEqualOneRender) {
  const fs::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  RunResult reference = runWavepath({"render", scene.string(), "-o", (dir / "single.exr").string(), "--spp", "16",
                                     "--width", "64", "--height", "48"});
  ASSERT_EQ(reference.exitCode, 0) << reference.err;

  const fs::path merged = dir / "merged.exr";
  submitAndWait("--tasks 4 --spp 16 " + quoted(merged) + " " + quoted(scene) + " --width 64 --height 48", "merge: ",
                merged.string() + ".parts");
  if (HasFatalFailure()) return;

  for (int task = 0; task < 4; ++task) {
    RadianceImage part = readExr(merged.string() + ".parts/part_" + std::to_string(task) + ".exr");
    ASSERT_TRUE(part.record.has_value());
    EXPECT_EQ(part.record->firstSample, 4u * task);
    EXPECT_EQ(part.record->lastSample, 4u * task + 3);
  }
  // Means to float rounding (farm_test's bound: sums of 16 non-negative floats grouped
  // otherwise), variances to a rounding of the mean square.
  RadianceImage whole = readExr(dir / "single.exr"), frame = readExr(merged);
  ASSERT_EQ(frame.mean.size(), whole.mean.size());
  for (size_t i = 0; i < whole.mean.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double m = whole.mean[i][c], v = whole.variance[i][c];
      ASSERT_LE(std::abs(frame.mean[i][c] - m), 1e-5 * m) << "pixel " << i << " channel " << c;
      ASSERT_LE(std::abs(frame.variance[i][c] - v), 1e-4 * v + 1e-6 * (m * m + 16.0 * v) / 15.0)
          << "pixel " << i << " channel " << c;
    }
  }
}

// Frames 0..4 of an animation over 3 tasks (runs of 1, 2 and 2 frames): each frame as a
// sequence render in one process makes it, bit for bit.
TEST_F(Slurm, ArrayOverFramesRendersEachFrameAsASequenceRenderDoes) {
  const fs::path scene = sourceDirectory() / "tests" / "data" / "anim_trs.gltf";
  const std::vector<std::string> flags = {"--width", "32", "--height", "24", "--spp", "4", "--fps", "2"};
  std::vector<std::string> sequence = {"render", scene.string(), "-o", (dir / "seq_##.exr").string(), "--frames",
                                       "0..4"};
  sequence.insert(sequence.end(), flags.begin(), flags.end());
  RunResult reference = runWavepath(sequence);
  ASSERT_EQ(reference.exitCode, 0) << reference.err;

  std::string arguments = "--tasks 3 --frames 0..4 " + quoted(dir / "farm_##.exr") + " " + quoted(scene);
  for (const std::string& flag : flags) arguments += " " + flag;
  // With --frames nothing is merged: wait for the array itself.
  submitAndWait(arguments, "render array: ", dir / "farm_##.exr.parts");
  if (HasFatalFailure()) return;
  for (int frame = 0; frame <= 4; ++frame) {
    const std::string number = "0" + std::to_string(frame);
    RadianceImage farm = readExr(dir / ("farm_" + number + ".exr")), seq = readExr(dir / ("seq_" + number + ".exr"));
    ASSERT_EQ(farm.mean.size(), seq.mean.size());
    for (size_t i = 0; i < seq.mean.size(); ++i) ASSERT_EQ(farm.mean[i], seq.mean[i]) << "frame " << frame << " pixel " << i;
  }
}

}  // namespace
}  // namespace wp::test
