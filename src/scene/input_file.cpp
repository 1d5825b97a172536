// Bounded reads of input files: the size is checked on the open descriptor (no race with the
// path being replaced), and the read stops at the limit even if the file grows meanwhile.
#include "scene/input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace gs {

bool read_input_file(const std::string &path, std::size_t max_bytes, std::string &contents,
                     std::string &error) {
  // O_NONBLOCK: opening a FIFO with no writer must not wait; regular files ignore it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    error = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  struct stat info {};
  bool ok = ::fstat(fd, &info) == 0;
  if (!ok) {
    error = std::string("cannot read: ") + std::strerror(errno);
  } else if (!S_ISREG(info.st_mode)) {
    error = S_ISDIR(info.st_mode) ? "is a directory, not a file" : "is not a regular file";
    ok = false;
  } else if (static_cast<std::size_t>(info.st_size) > max_bytes) {
    error = "the file has " + std::to_string(info.st_size) + " bytes, more than the limit of " +
            std::to_string(max_bytes);
    ok = false;
  }
  std::string read;
  if (ok) {
    read.resize(static_cast<std::size_t>(info.st_size));
    std::size_t got = 0;
    while (got < read.size()) {
      const ssize_t n = ::read(fd, read.data() + got, read.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        error = std::string("cannot read: ") + std::strerror(errno);
        ok = false;
        break;
      }
      if (n == 0) break;  // the file shrank since fstat: keep what is there
      got += static_cast<std::size_t>(n);
    }
    read.resize(got);
  }
  ::close(fd);
  if (ok) contents = std::move(read);
  return ok;
}

}  // namespace gs
