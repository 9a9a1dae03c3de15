// The Slurm recipe end to end: a single-node cluster on localhost started by the test
// (tools/slurm/local-cluster: munged, slurmctld and slurmd with their own pid files, stopped
// by those pids whatever happens), the 4-task array of Cornell-box sample batches and its
// dependent merge job submitted by tools/slurm/submit, and the merged image checked against
// one render of all the samples. A machine where the daemons cannot start fails, saying why.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "image/image_io.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

namespace fs = std::filesystem;

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr
};

CommandResult runCommand(const std::string& command) {
  CommandResult result;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

class Slurm : public ::testing::Test {
protected:
  void SetUp() override {
    dir = scratchDirectory("slurm");
    cluster = dir / "cluster";
    // The cluster also stops when this test process ends, killed or not.
    CommandResult start = runCommand(script("local-cluster") + " start '" + cluster.string() + "' " +
                                     std::to_string(::getpid()));
    ASSERT_EQ(start.exitCode, 0) << "no Slurm cluster on this machine:\n" << start.output;
  }
  void TearDown() override { runCommand(script("local-cluster") + " stop '" + cluster.string() + "'"); }

  std::string script(const std::string& name) { return "'" + (sourceDirectory() / "tools" / "slurm" / name).string() + "'"; }
  std::string slurm(const std::string& command) {
    return "env SLURM_CONF='" + (cluster / "slurm.conf").string() + "' " + command;
  }

  // The job's state (PENDING, RUNNING, COMPLETED, FAILED, ...) as scontrol reports it.
  std::string jobState(const std::string& id) {
    std::string out = runCommand(slurm("scontrol show job -o " + id)).output;
    size_t at = out.find("JobState=");
    return at == std::string::npos ? "unknown (" + out + ")" : out.substr(at + 9, out.find(' ', at) - at - 9);
  }

  fs::path dir, cluster;
};

TEST_F(Slurm, FourTaskArrayAndMergeJobEqualOneRender) {
  const fs::path scene = sourceDirectory() / "assets" / "cornell-box.gltf";
  const std::vector<std::string> flags = {"--width", "64", "--height", "48"};
  std::vector<std::string> single = {"render", scene.string(), "-o", (dir / "single.exr").string(), "--spp", "16"};
  single.insert(single.end(), flags.begin(), flags.end());
  RunResult reference = runWavepath(single);
  ASSERT_EQ(reference.exitCode, 0) << reference.err;

  // The jobs inherit this environment: validation on, the test run's OpenCL cache.
  const fs::path merged = dir / "merged.exr";
  CommandResult submit = runCommand(slurm("WAVEPATH_VALIDATION=1 WAVEPATH_CACHE_DIR='" WAVEPATH_TEST_CACHE_DIR "' " +
                                          script("submit") + " --tasks 4 --spp 16 --wavepath '" WAVEPATH_EXE "' '" +
                                          merged.string() + "' '" + scene.string() + "' --width 64 --height 48"));
  ASSERT_EQ(submit.exitCode, 0) << submit.output;
  const size_t at = submit.output.find("merge: ");
  ASSERT_NE(at, std::string::npos) << submit.output;
  const std::string mergeJob = submit.output.substr(at + 7, submit.output.find('\n', at) - at - 7);

  std::string state;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(150);
  while ((state = jobState(mergeJob)) != "COMPLETED" && std::chrono::steady_clock::now() < deadline) {
    ASSERT_TRUE(state == "PENDING" || state == "RUNNING" || state == "CONFIGURING" || state == "COMPLETING")
        << "merge job " << mergeJob << " is " << state << "\n"
        << runCommand("tail -n 5 '" + (merged.string() + ".parts") + "'/*.log").output;
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  ASSERT_EQ(state, "COMPLETED") << "the merge job did not complete in 150 s\n"
                                << runCommand(slurm("squeue")).output;

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

}  // namespace
}  // namespace wp::test
