// Runs wavepath in a subprocess for end-to-end tests.
#include "support/run_wavepath.h"

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

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
