// Atomic file writes: a temporary file beside the target, fsync, rename, fsync of the directory.
#include "core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
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

}  // namespace

void writeFileAtomically(const fs::path& path, const std::vector<unsigned char>& bytes, const char* what) {
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
