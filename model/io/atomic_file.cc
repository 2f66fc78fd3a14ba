#include "model/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

namespace tpopt {
namespace {

Status Fail(const std::string& path, const std::string& what, int error) {
  return Status::Error(path + ": cannot " + what + ": " + std::strerror(error));
}

// The process umask, read without setting it: umask(2) can only be queried
// by changing it, which would race with threads creating files meanwhile.
mode_t CurrentUmask() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "Umask:") {
      std::string octal;
      status >> octal;
      return static_cast<mode_t>(std::strtoul(octal.c_str(), nullptr, 8));
    }
    status.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return 022;
}

// mkstemp makes files 0600. A replaced file keeps its permissions; a new
// one gets what open(2) would give, 0666 less the umask.
mode_t ModeFor(const std::string& path) {
  struct stat st;
  if (stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) return st.st_mode & 07777;
  return 0666 & ~CurrentUmask();
}

}  // namespace

Status WriteFileAtomically(const std::string& path, const std::string& contents) {
  std::string pattern = path + ".tmp.XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = mkstemp(name.data());
  if (fd < 0) return Fail(path, "create a file there", errno);
  const std::string tmp(name.data());
  size_t written = 0;
  while (written < contents.size()) {
    const ssize_t n = write(fd, contents.data() + written, contents.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      close(fd);
      unlink(tmp.c_str());
      return Fail(path, "write", error);
    }
    written += static_cast<size_t>(n);
  }
  // Best effort: a file with the wrong mode is still better than none.
  fchmod(fd, ModeFor(path));
  // Data on disk before the rename, so a crash leaves the old file or the
  // new one, never a renamed empty one. Close even when fsync fails.
  const int sync_error = fsync(fd) == 0 ? 0 : errno;
  const int close_error = close(fd) == 0 ? 0 : errno;
  if (sync_error != 0 || close_error != 0) {
    unlink(tmp.c_str());
    return Fail(path, "flush", sync_error != 0 ? sync_error : close_error);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    unlink(tmp.c_str());
    return Fail(path, "rename the temporary file onto it", error);
  }
  return Status::Ok();
}

}  // namespace tpopt
