// Reading a whole regular file of a bounded size, opened so that nothing else can block.
#include "core/file_read.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

namespace wp {
namespace {

std::string mebibytes(uint64_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

// Closes the descriptor on every exit path.
struct FileDescriptor {
  int fd = -1;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::vector<unsigned char> readRegularFile(const std::filesystem::path& file, const std::string& label,
                                           uint64_t maxBytes, const std::string& expected) {
  const auto fail = [&](const std::string& message) { throw Error(label + ": " + message); };
  // O_NONBLOCK: opening a FIFO must not wait for a writer; fstat on the open file then
  // decides, so the file cannot be swapped between the check and the read.
  FileDescriptor in{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (in.fd < 0) {
    if (errno == ENOENT) fail("no such file; check the path");
    fail(std::string("cannot be opened (") + std::strerror(errno) + "); check the path and its permissions");
  }
  struct stat status {};
  if (::fstat(in.fd, &status) != 0) fail(std::string("cannot be examined (") + std::strerror(errno) + ")");
  if (S_ISDIR(status.st_mode)) fail("is a directory; give the path of " + expected);
  if (!S_ISREG(status.st_mode)) {
    fail("is not a regular file (a FIFO, socket or device); give the path of " + expected);
  }
  const auto size = static_cast<uint64_t>(status.st_size);
  if (size == 0) fail("is empty; give the path of " + expected);
  if (size > maxBytes) {
    fail("is " + mebibytes(size) + ", more than the " + mebibytes(maxBytes) + " wavepath reads as " + expected +
         "; check that it is the right file");
  }
  std::vector<unsigned char> bytes(static_cast<size_t>(size));
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(in.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(std::string("could not be read (") + std::strerror(errno) + ")");
    if (n == 0) fail("ended before its size said; check that nothing else is writing it");
    done += static_cast<size_t>(n);
  }
  return bytes;
}

}  // namespace wp
