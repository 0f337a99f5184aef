// Reading and writing open files on Windows, through the C runtime's descriptors, always in
// binary mode (file_io.h).
#include "platform/file_io.h"

#include <algorithm>
#include <cerrno>
#include <climits>

#include <fcntl.h>
#include <io.h>
#include <sys/stat.h>

#include "platform/file_status.h"
#include "platform/utf8.h"

namespace vkrt::platform {
namespace {

// The C runtime reads and writes at most INT_MAX bytes a call.
unsigned chunk(std::size_t size) { return static_cast<unsigned>(std::min<std::size_t>(size, INT_MAX)); }

// Runs `io` at `offset` and puts the file's position back, as pread and pwrite leave it.
template <class Io>
std::int64_t atOffset(int fd, std::uint64_t offset, Io io) {
  const __int64 position = ::_telli64(fd);
  if (position < 0 || ::_lseeki64(fd, static_cast<__int64>(offset), SEEK_SET) < 0) return -1;
  const std::int64_t n = io();
  const int error = errno;
  ::_lseeki64(fd, position, SEEK_SET);
  errno = error;
  return n;
}

}  // namespace

int openForReading(const std::string& path) {
  const int fd = ::_wopen(wideFromUtf8(path).c_str(), _O_RDONLY | _O_BINARY | _O_NOINHERIT);
  if (fd < 0 && errno == EACCES && isDirectory(path)) errno = EISDIR;   // as POSIX's read says
  return fd;
}

int openForAppending(const std::string& path, unsigned mode) {
  // Windows has no O_NOFOLLOW; a symbolic link there needs an administrator or developer mode.
  return ::_wopen(wideFromUtf8(path).c_str(), _O_WRONLY | _O_APPEND | _O_CREAT | _O_BINARY | _O_NOINHERIT,
                  (mode & 0200) != 0 ? _S_IREAD | _S_IWRITE : _S_IREAD);
}

std::int64_t readSome(int fd, void* data, std::size_t size) { return ::_read(fd, data, chunk(size)); }

std::int64_t readSomeAt(int fd, void* data, std::size_t size, std::uint64_t offset) {
  return atOffset(fd, offset, [&] { return std::int64_t{::_read(fd, data, chunk(size))}; });
}

std::int64_t writeSome(int fd, const void* data, std::size_t size) { return ::_write(fd, data, chunk(size)); }

std::int64_t writeSomeAt(int fd, const void* data, std::size_t size, std::uint64_t offset) {
  return atOffset(fd, offset, [&] { return std::int64_t{::_write(fd, data, chunk(size))}; });
}

int syncFile(int fd) { return ::_commit(fd); }

int closeFile(int fd) { return ::_close(fd); }

}  // namespace vkrt::platform
