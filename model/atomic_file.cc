#include "model/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace tpopt {
namespace {

Status Fail(const std::string& path, const std::string& what, int error) {
  return Status::Error(path + ": cannot " + what + ": " + std::strerror(error));
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
  // Files written with mkstemp are 0600; give them the usual 0644 less umask.
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  if (fsync(fd) != 0 || close(fd) != 0) {
    const int error = errno;
    unlink(tmp.c_str());
    return Fail(path, "flush", error);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    unlink(tmp.c_str());
    return Fail(path, "rename the temporary file onto it", error);
  }
  return Status::Ok();
}

}  // namespace tpopt
