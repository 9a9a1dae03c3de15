// Runs the wavepath executable as a user would, capturing exit code and output.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace wp::test {

struct RunResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

// Runs `wavepath args...` with extra environment assignments ("NAME=value"), with the
// Vulkan validation layer on (WAVEPATH_VALIDATION=1) and the OpenCL program cache of the
// test run (WAVEPATH_CACHE_DIR) unless env overrides them; kills it after timeoutSeconds so
// a hang fails the test instead of stalling the suite.
RunResult runWavepath(const std::vector<std::string>& args, const std::vector<std::string>& env = {},
                      int timeoutSeconds = 600);

// Expects exactly one line on stderr, "wavepath: error: ..." containing `phrase`, and exit
// code `code` (1: bad input or device, 2: bad flags).
void expectOneErrorLine(const RunResult& r, const std::string& phrase, int code = 1);

// A wavepath started in the background (as runWavepath starts it, without the timeout
// wrapper, so signals reach wavepath itself).
struct WavepathProcess {
  int pid = -1;
  std::filesystem::path dir;  // holds its out and err
  // Whether it has exited (then reaped, its status kept for waitWavepath).
  bool ended();
  bool reaped = false;
  int status = 0;
};
WavepathProcess startWavepath(const std::vector<std::string>& args);
// Waits for it to end (killing it after timeoutSeconds) and returns what it left.
RunResult waitWavepath(WavepathProcess& process, int timeoutSeconds = 600);

// Runs a shell command line; its stdout and stderr together end up in `out`.
RunResult runShell(const std::string& command);

// The wavepath executable under test.
std::filesystem::path wavepathExecutable();

// A fresh empty directory for one test's files.
std::filesystem::path scratchDirectory(const std::string& name);

// The repository root (WAVEPATH_SOURCE_DIR, set by ctest).
std::filesystem::path sourceDirectory();

}  // namespace wp::test
