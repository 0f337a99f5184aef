// The status of a file on POSIX: stat, lstat, fstat (file_status.h).
#include "platform/file_status.h"

#include <cerrno>

#include <sys/stat.h>

namespace vkrt::platform {
namespace {

FileKind kindOf(mode_t mode) {
  if (S_ISREG(mode)) return FileKind::Regular;
  if (S_ISDIR(mode)) return FileKind::Directory;
  if (S_ISCHR(mode)) return FileKind::CharacterDevice;
  if (S_ISBLK(mode)) return FileKind::BlockDevice;
  if (S_ISFIFO(mode)) return FileKind::Fifo;
  if (S_ISSOCK(mode)) return FileKind::Socket;
  if (S_ISLNK(mode)) return FileKind::SymbolicLink;
  return FileKind::Other;
}

// The status from a stat call's result (0, or -1 with errno set).
FileStatus statusFrom(int result, const struct stat& st) {
  FileStatus s;
  if (result != 0) {
    s.error = errno;
    return s;
  }
  s.kind = kindOf(st.st_mode);
  s.size = static_cast<std::uint64_t>(st.st_size);
  s.identity = {static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)};
  s.links = static_cast<std::uint64_t>(st.st_nlink);
  s.mode = static_cast<unsigned>(st.st_mode & 07777);
  s.uid = static_cast<unsigned>(st.st_uid);
  s.gid = static_cast<unsigned>(st.st_gid);
  return s;
}

}  // namespace

FileStatus statusOf(const std::string& path) {
  struct stat st {};
  const int result = ::stat(path.c_str(), &st);
  return statusFrom(result, st);
}

FileStatus linkStatusOf(const std::string& path) {
  struct stat st {};
  const int result = ::lstat(path.c_str(), &st);
  return statusFrom(result, st);
}

FileStatus statusOfOpen(int fd) {
  struct stat st {};
  const int result = ::fstat(fd, &st);
  return statusFrom(result, st);
}

FileStatus statusOfOpen(std::FILE* stream) { return statusOfOpen(::fileno(stream)); }

}  // namespace vkrt::platform
