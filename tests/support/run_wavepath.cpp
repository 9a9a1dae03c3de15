// Runs wavepath in a subprocess for end-to-end tests.
#include "support/run_wavepath.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace wp::test {
namespace {

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return q + "'";
}

std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

RunResult runWavepath(const std::vector<std::string>& args, const std::vector<std::string>& env,
                      int timeoutSeconds) {
  std::filesystem::path dir = scratchDirectory("run");
  std::string command = "env WAVEPATH_VALIDATION=1 " + quote("WAVEPATH_CACHE_DIR=" WAVEPATH_TEST_CACHE_DIR);
  for (const std::string& e : env) {
    command += " " + quote(e);
  }
  command += " timeout -s KILL " + std::to_string(timeoutSeconds) + " " + quote(WAVEPATH_EXE);
  for (const std::string& a : args) {
    command += " " + quote(a);
  }
  command += " >" + quote((dir / "out").string()) + " 2>" + quote((dir / "err").string()) + " </dev/null";
  int status = std::system(command.c_str());
  RunResult result;
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = slurp(dir / "out");
  result.err = slurp(dir / "err");
  return result;
}

void expectOneErrorLine(const RunResult& r, const std::string& phrase, int code) {
  EXPECT_EQ(r.exitCode, code) << r.err;
  std::string lastLine = r.err;
  while (!lastLine.empty() && lastLine.back() == '\n') {
    lastLine.pop_back();
  }
  size_t nl = lastLine.rfind('\n');
  lastLine = nl == std::string::npos ? lastLine : lastLine.substr(nl + 1);
  EXPECT_EQ(lastLine.rfind("wavepath: error: ", 0), 0u) << r.err;
  EXPECT_NE(lastLine.find(phrase), std::string::npos) << "expected '" << phrase << "' in: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "more than one line: " << r.err;
}

WavepathProcess startWavepath(const std::vector<std::string>& args) {
  WavepathProcess process;
  process.dir = scratchDirectory("process");
  const std::string out = (process.dir / "out").string(), err = (process.dir / "err").string();
  std::vector<std::string> argv = {WAVEPATH_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  process.pid = ::fork();
  if (process.pid == 0) {
    ::setenv("WAVEPATH_VALIDATION", "1", 1);
    ::setenv("WAVEPATH_CACHE_DIR", WAVEPATH_TEST_CACHE_DIR, 1);
    int in = ::open("/dev/null", O_RDONLY);
    int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(in, 0);
    ::dup2(o, 1);
    ::dup2(e, 2);
    std::vector<char*> pointers;
    for (std::string& a : argv) pointers.push_back(a.data());
    pointers.push_back(nullptr);
    ::execv(pointers[0], pointers.data());
    ::_exit(127);
  }
  return process;
}

bool WavepathProcess::ended() {
  if (!reaped && ::waitpid(pid, &status, WNOHANG) == pid) reaped = true;
  return reaped;
}

RunResult waitWavepath(WavepathProcess& process, int timeoutSeconds) {
  RunResult result;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
  int& status = process.status;
  while (!process.ended()) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(process.pid, SIGKILL);
      ::waitpid(process.pid, &status, 0);
      process.reaped = true;
      result.err = "(killed after " + std::to_string(timeoutSeconds) + " s)\n";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = slurp(process.dir / "out");
  result.err += slurp(process.dir / "err");
  return result;
}

RunResult runShell(const std::string& command) {
  RunResult result;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.out.append(buffer, n);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::filesystem::path wavepathExecutable() { return WAVEPATH_EXE; }

std::filesystem::path scratchDirectory(const std::string& name) {
  static int counter = 0;
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("wavepath-test-" + std::to_string(::getpid()) + "-" + name + "-" +
                               std::to_string(counter++));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path sourceDirectory() {
  const char* dir = std::getenv("WAVEPATH_SOURCE_DIR");
  if (dir == nullptr) {
    throw std::runtime_error("WAVEPATH_SOURCE_DIR is not set; run the tests through ctest");
  }
  return dir;
}

}  // namespace wp::test
