// Where symbolic links lead on Windows (file_names.h): the reparse point of a symbolic link
// (FSCTL_GET_REPARSE_POINT), the final name of an open handle (GetFinalPathNameByHandleW).
#include "platform/file_names.h"

#include <cerrno>
#include <cstring>
#include <vector>

#define WIN32_LEAN_AND_MEAN
#ifndef NOMINMAX
#  define NOMINMAX   // std::min and std::max, not windows.h's macros
#endif
#include <windows.h>
#include <winioctl.h>

#include "platform/utf8.h"
#include "platform/win32_errors.h"

namespace vkrt::platform {
namespace {

// The head of a symbolic link's REPARSE_DATA_BUFFER (ntifs.h, which user programs lack).
struct SymbolicLinkReparse {
  ULONG tag;
  USHORT dataLength, reserved;
  USHORT substituteOffset, substituteLength, printOffset, printLength;
  ULONG flags;
  // then the path buffer: UTF-16, offsets and lengths in bytes
};
constexpr std::size_t kMaxReparseBytes = 16 * 1024;   // MAXIMUM_REPARSE_DATA_BUFFER_SIZE

// `path` opened for its attributes alone (a folder too), through a final symbolic link unless
// `followLinks` is false; INVALID_HANDLE_VALUE with errno set when it cannot be.
HANDLE openForAttributes(const std::string& path, bool followLinks) {
  const DWORD flags = FILE_FLAG_BACKUP_SEMANTICS | (followLinks ? 0 : FILE_FLAG_OPEN_REPARSE_POINT);
  HANDLE h = ::CreateFileW(wideFromUtf8(path).c_str(), 0, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
                           nullptr, OPEN_EXISTING, flags, nullptr);
  if (h == INVALID_HANDLE_VALUE) errno = path.empty() ? ENOENT : errnoFromWin32(::GetLastError());
  return h;
}

}  // namespace

std::optional<std::string> readSymbolicLink(const std::string& path) {
  HANDLE h = openForAttributes(path, false);
  if (h == INVALID_HANDLE_VALUE) return std::nullopt;
  std::vector<unsigned char> buffer(kMaxReparseBytes);
  DWORD bytes = 0;
  const BOOL ok = ::DeviceIoControl(h, FSCTL_GET_REPARSE_POINT, nullptr, 0, buffer.data(),
                                    static_cast<DWORD>(buffer.size()), &bytes, nullptr);
  const DWORD error = ::GetLastError();
  ::CloseHandle(h);
  if (!ok) {
    errno = errnoFromWin32(error);   // ERROR_NOT_A_REPARSE_POINT: EINVAL, as readlink says
    return std::nullopt;
  }
  SymbolicLinkReparse head{};
  if (bytes < sizeof head) {
    errno = EINVAL;
    return std::nullopt;
  }
  std::memcpy(&head, buffer.data(), sizeof head);
  if (head.tag != IO_REPARSE_TAG_SYMLINK) {   // a junction or another kind of reparse point
    errno = EINVAL;
    return std::nullopt;
  }
  // The printed name is the link's text as made ("..\\b.png", "C:\\x"); the substitute name is
  // the same in NT's spelling ("\\??\\C:\\x"), used when no printed name was stored.
  const bool printed = head.printLength > 0;
  const std::size_t offset = sizeof head + (printed ? head.printOffset : head.substituteOffset);
  const std::size_t length = printed ? head.printLength : head.substituteLength;
  if (offset + length > bytes) {
    errno = EINVAL;
    return std::nullopt;
  }
  std::wstring text(length / sizeof(wchar_t), L'\0');
  std::memcpy(text.data(), buffer.data() + offset, text.size() * sizeof(wchar_t));
  if (!printed && text.rfind(L"\\??\\", 0) == 0) text.erase(0, 4);
  return utf8FromWide(text);
}

std::optional<std::string> realPath(const std::string& path) {
  HANDLE h = openForAttributes(path, true);
  if (h == INVALID_HANDLE_VALUE) return std::nullopt;
  std::wstring name(MAX_PATH, L'\0');
  DWORD n = 0;
  for (;;) {
    n = ::GetFinalPathNameByHandleW(h, name.data(), static_cast<DWORD>(name.size()),
                                    FILE_NAME_NORMALIZED | VOLUME_NAME_DOS);
    if (n < name.size()) break;
    name.resize(n);   // too small: n is the size needed, with the terminating zero
  }
  const DWORD error = ::GetLastError();
  ::CloseHandle(h);
  if (n == 0) {
    errno = errnoFromWin32(error);
    return std::nullopt;
  }
  name.resize(n);
  // "\\?\C:\dir\file" -> "C:\dir\file"; "\\?\UNC\server\share\file" -> "\\server\share\file".
  if (name.rfind(L"\\\\?\\UNC\\", 0) == 0)
    name.replace(0, 8, L"\\\\");
  else if (name.rfind(L"\\\\?\\", 0) == 0)
    name.erase(0, 4);
  return utf8FromWide(name);
}

}  // namespace vkrt::platform
