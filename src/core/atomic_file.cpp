// Atomic file writes: a temporary file beside the target, fsync, rename, fsync of the directory.
#include "core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cerrno>
#include <cstring>
#include <string>

#include "core/error.h"

namespace wp {
namespace fs = std::filesystem;

namespace {

// Closes and removes the temporary file unless the write succeeded and renamed it into place.
struct TempFileGuard {
  fs::path path;
  int fd = -1;
  bool renamed = false;
  ~TempFileGuard() {
    if (fd >= 0) ::close(fd);
    if (!renamed) ::unlink(path.c_str());
  }
};

std::string systemError(int error) { return std::strerror(error); }

// The signals that end a process by default: Ctrl-C, kill, a closed terminal, Ctrl-\.
constexpr std::array<int, 4> kTerminationSignals = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
volatile std::sig_atomic_t gDeferredSignal = 0;
extern "C" void deferSignal(int signal) { gDeferredSignal = signal; }

// While it lives, a termination signal (whichever thread gets it) is only noted; when it
// ends, the previous handlers come back (the render's own, app/interrupt.h, or the default)
// and a noted signal is raised again, with the effect it would have had. Not for concurrent
// use: files are written one at a time.
class TerminationSignalsDeferred {
public:
  TerminationSignalsDeferred() {
    struct sigaction defer {};
    defer.sa_handler = deferSignal;
    defer.sa_flags = SA_RESTART;
    sigemptyset(&defer.sa_mask);
    for (size_t i = 0; i < kTerminationSignals.size(); ++i) sigaction(kTerminationSignals[i], &defer, &previous_[i]);
  }
  ~TerminationSignalsDeferred() {
    for (size_t i = 0; i < kTerminationSignals.size(); ++i) sigaction(kTerminationSignals[i], &previous_[i], nullptr);
    if (const int signal = gDeferredSignal) {
      gDeferredSignal = 0;
      std::raise(signal);
    }
  }
  TerminationSignalsDeferred(const TerminationSignalsDeferred&) = delete;
  TerminationSignalsDeferred& operator=(const TerminationSignalsDeferred&) = delete;

private:
  std::array<struct sigaction, kTerminationSignals.size()> previous_{};
};

}  // namespace

void writeFileAtomically(const fs::path& path, const std::vector<unsigned char>& bytes, const char* what) {
  // Declared first, so that it ends after the temporary file is renamed or removed: Ctrl-C
  // during the write used to leave a hidden .NAME.tmpPID_N of several MB.
  const TerminationSignalsDeferred deferred;
  auto fail = [&](const std::string& reason) {
    throw Error(std::string("cannot write ") + what + " '" + path.string() + "': " + reason);
  };
  static std::atomic<unsigned> counter{0};
  const fs::path directory = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::string tempName = ".";  // hidden; appended piecewise to dodge a GCC 12 -Wrestrict false positive
  tempName += path.filename().string();
  tempName += ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
  fs::path tempPath = directory / tempName;
  int fd = ::open(tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) fail(systemError(errno) + "; check the directory's permissions and free space");
  TempFileGuard temp{tempPath, fd};
  size_t written = 0;
  while (written < bytes.size()) {
    ssize_t n = ::write(temp.fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(systemError(errno) + "; check free space and try again");
    written += static_cast<size_t>(n);
  }
  int syncError = ::fsync(temp.fd) == 0 ? 0 : errno;
  int closeError = ::close(temp.fd) == 0 ? 0 : errno;
  temp.fd = -1;
  if (syncError || closeError) fail(systemError(syncError ? syncError : closeError) + "; check free space and try again");
  if (::rename(temp.path.c_str(), path.c_str()) != 0) fail(systemError(errno) + "; check the output path");
  temp.renamed = true;
  // The rename itself reaches the disk with the directory: after a power cut the file is then
  // the new one, not the old one or none.
  int dirFd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dirFd >= 0) {
    ::fsync(dirFd);
    ::close(dirFd);
  }
}

}  // namespace wp
