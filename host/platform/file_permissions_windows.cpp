// Permission bits on Windows: the read-only attribute (file_permissions.h).
#include "platform/file_permissions.h"

#include <cerrno>

#define WIN32_LEAN_AND_MEAN
#ifndef NOMINMAX
#  define NOMINMAX   // std::min and std::max, not windows.h's macros
#endif
#include <windows.h>
#include <io.h>
#include <sys/stat.h>

#include "platform/utf8.h"
#include "platform/win32_errors.h"

namespace vkrt::platform {

int setMode(const std::string& path, unsigned mode) {
  return ::_wchmod(wideFromUtf8(path).c_str(), (mode & 0200) != 0 ? _S_IREAD | _S_IWRITE : _S_IREAD);
}

int setOpenMode(int fd, unsigned mode) {
  const auto h = reinterpret_cast<HANDLE>(::_get_osfhandle(fd));
  if (h == INVALID_HANDLE_VALUE) {
    errno = EBADF;
    return -1;
  }
  FILE_BASIC_INFO info{};
  if (!::GetFileInformationByHandleEx(h, FileBasicInfo, &info, sizeof info)) return failWithLastError();
  const DWORD attributes = (mode & 0200) != 0 ? info.FileAttributes & ~DWORD{FILE_ATTRIBUTE_READONLY}
                                              : info.FileAttributes | FILE_ATTRIBUTE_READONLY;
  if (attributes == info.FileAttributes) return 0;
  // Zero times are left as they are; zero attributes would be too, hence FILE_ATTRIBUTE_NORMAL.
  FILE_BASIC_INFO change{};
  change.FileAttributes = attributes != 0 ? attributes : FILE_ATTRIBUTE_NORMAL;
  if (!::SetFileInformationByHandle(h, FileBasicInfo, &change, sizeof change)) return failWithLastError();
  return 0;
}

int setOpenOwner(int, unsigned, unsigned) { return 0; }

bool changesOwners() { return false; }

unsigned creationMask() {
  const int mask = ::_umask(0);
  ::_umask(mask);
  return static_cast<unsigned>(mask);
}

bool isWritable(const std::string& path) { return ::_waccess(wideFromUtf8(path).c_str(), 2) == 0; }

}  // namespace vkrt::platform
