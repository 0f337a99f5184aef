// The status of a file on Windows, from an open handle (file_status.h): GetFileInformationByHandle
// gives the volume serial number, the file index and the number of names, which mingw's stat
// does not (st_ino 0, st_nlink 1 for every file).
#include "platform/file_status.h"

#include <cerrno>
#include <cstdio>

#define WIN32_LEAN_AND_MEAN
#ifndef NOMINMAX
#  define NOMINMAX   // std::min and std::max, not windows.h's macros
#endif
#include <windows.h>
#include <io.h>

#include "platform/utf8.h"
#include "platform/win32_errors.h"

namespace vkrt::platform {
namespace {

FileStatus failed(int error) {
  FileStatus s;
  s.error = error;
  return s;
}

// The status of the file `h` is open on. `link`: `h` was opened on a symbolic link itself.
FileStatus statusOfHandle(HANDLE h, bool link) {
  FileStatus s;
  s.links = 1;
  switch (::GetFileType(h)) {
    case FILE_TYPE_CHAR:   // NUL, CON, a serial port
      s.kind = FileKind::CharacterDevice;
      s.mode = 0666;
      return s;
    case FILE_TYPE_PIPE:   // a pipe or a socket
      s.kind = FileKind::Fifo;
      s.mode = 0666;
      return s;
    default: break;
  }
  BY_HANDLE_FILE_INFORMATION info{};
  if (!::GetFileInformationByHandle(h, &info)) return failed(errnoFromWin32(::GetLastError()));
  const bool directory = (info.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY) != 0;
  const bool readOnly = (info.dwFileAttributes & FILE_ATTRIBUTE_READONLY) != 0;
  s.kind = directory ? FileKind::Directory : FileKind::Regular;
  if (link && (info.dwFileAttributes & FILE_ATTRIBUTE_REPARSE_POINT) != 0) {
    FILE_ATTRIBUTE_TAG_INFO tag{};
    if (::GetFileInformationByHandleEx(h, FileAttributeTagInfo, &tag, sizeof tag) &&
        tag.ReparseTag == IO_REPARSE_TAG_SYMLINK)
      s.kind = FileKind::SymbolicLink;
  }
  s.size = std::uint64_t{info.nFileSizeHigh} << 32 | info.nFileSizeLow;
  s.identity = {info.dwVolumeSerialNumber, std::uint64_t{info.nFileIndexHigh} << 32 | info.nFileIndexLow};
  s.links = info.nNumberOfLinks;
  s.mode = directory ? (readOnly ? 0555u : 0777u) : (readOnly ? 0444u : 0666u);
  return s;
}

FileStatus statusAt(const std::string& path, bool followLinks) {
  // No access asked for (attributes only): opens a file another program holds open without
  // sharing, and a folder (FILE_FLAG_BACKUP_SEMANTICS).
  const DWORD flags = FILE_FLAG_BACKUP_SEMANTICS | (followLinks ? 0 : FILE_FLAG_OPEN_REPARSE_POINT);
  HANDLE h = ::CreateFileW(wideFromUtf8(path).c_str(), 0, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
                           nullptr, OPEN_EXISTING, flags, nullptr);
  if (h == INVALID_HANDLE_VALUE) return failed(path.empty() ? ENOENT : errnoFromWin32(::GetLastError()));
  FileStatus s = statusOfHandle(h, !followLinks);
  ::CloseHandle(h);
  return s;
}

}  // namespace

FileStatus statusOf(const std::string& path) { return statusAt(path, true); }

FileStatus linkStatusOf(const std::string& path) { return statusAt(path, false); }

FileStatus statusOfOpen(int fd) {
  const auto h = reinterpret_cast<HANDLE>(::_get_osfhandle(fd));
  if (h == INVALID_HANDLE_VALUE) return failed(EBADF);
  return statusOfHandle(h, false);
}

FileStatus statusOfOpen(std::FILE* stream) { return statusOfOpen(::_fileno(stream)); }

}  // namespace vkrt::platform
