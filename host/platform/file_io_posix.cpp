// Reading and writing open files on POSIX (file_io.h).
#include "platform/file_io.h"

#include <cerrno>

#include <fcntl.h>
#include <unistd.h>

namespace vkrt::platform {

int openForReading(const std::string& path) { return ::open(path.c_str(), O_RDONLY | O_CLOEXEC); }

int openForAppending(const std::string& path, unsigned mode) {
  return ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, static_cast<mode_t>(mode));
}

std::int64_t readSome(int fd, void* data, std::size_t size) { return ::read(fd, data, size); }

std::int64_t readSomeAt(int fd, void* data, std::size_t size, std::uint64_t offset) {
  return ::pread(fd, data, size, static_cast<off_t>(offset));
}

std::int64_t writeSome(int fd, const void* data, std::size_t size) { return ::write(fd, data, size); }

std::int64_t writeSomeAt(int fd, const void* data, std::size_t size, std::uint64_t offset) {
  return ::pwrite(fd, data, size, static_cast<off_t>(offset));
}

int syncFile(int fd) { return ::fsync(fd); }

int closeFile(int fd) { return ::close(fd); }

}  // namespace vkrt::platform
