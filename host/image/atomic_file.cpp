// Atomic file writing: mkstemps beside the target, fsync, rename. Ctrl-C between the two
// leaves the old file (the temporary file is registered with host/interrupt.h, which
// removes it on a second signal).
#include "image/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "errors.h"
#include "interrupt.h"

namespace vkrt {
namespace {

std::string directoryOf(const std::string& path) {
  std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

}  // namespace

void writeAll(int fd, const std::uint8_t* data, std::size_t size, const std::string& path) {
  while (size > 0) {
    ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw IoError("cannot write '" + path + "': " + std::strerror(errno));
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

void checkOutputWritable(const std::string& path) {
  if (path.empty()) throw IoError("output path is empty");
  std::string dir = directoryOf(path);
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw IoError("output directory '" + dir + "' does not exist");
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw IoError("output path '" + path + "' is a directory");
  // Creating a file is the only reliable test (permissions, read-only mounts, root).
  std::string probe = (std::filesystem::path(dir) / ".vkrt-XXXXXX.probe").string();
  int fd = ::mkstemps(probe.data(), 6);
  if (fd < 0) throw IoError("output directory '" + dir + "' is not writable: " + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

void writeFileAtomic(const std::string& path, const char* suffix, const std::function<void(int fd)>& write) {
  std::string tmpl = (std::filesystem::path(directoryOf(path)) / (std::string(".vkrt-XXXXXX") + suffix)).string();
  int fd = ::mkstemps(tmpl.data(), static_cast<int>(std::strlen(suffix)));
  if (fd < 0) throw IoError("cannot create a temporary file in '" + directoryOf(path) + "': " + std::strerror(errno));
  registerTemporaryFile(tmpl.c_str());
  try {
    // The file gets the permissions a plain create would give it (mkstemp makes it 0600).
    mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    waitForSignalIfTesting("write");
    write(fd);
    if (::fsync(fd) != 0 && errno != EINVAL) throw IoError("cannot write '" + path + "': " + std::strerror(errno));
    int closed = ::close(fd);
    fd = -1;
    if (closed != 0) throw IoError("cannot write '" + path + "': " + std::strerror(errno));
    throwIfInterrupted();   // the last moment at which the old file is still there
    if (::rename(tmpl.c_str(), path.c_str()) != 0)
      throw IoError("cannot write '" + path + "': " + std::strerror(errno));
  } catch (...) {
    if (fd >= 0) ::close(fd);
    ::unlink(tmpl.c_str());
    registerTemporaryFile(nullptr);
    throw;
  }
  registerTemporaryFile(nullptr);
}

}  // namespace vkrt
