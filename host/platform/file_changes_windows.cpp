// Making, replacing and removing files on Windows (file_changes.h): wide-character calls, an
// exclusive create for temporary names, MoveFileExW retried while a viewer holds the target.
#include "platform/file_changes.h"

#include <cerrno>
#include <chrono>
#include <random>
#include <thread>

#define WIN32_LEAN_AND_MEAN
#ifndef NOMINMAX
#  define NOMINMAX   // std::min and std::max, not windows.h's macros
#endif
#include <windows.h>
#include <direct.h>
#include <fcntl.h>
#include <io.h>
#include <share.h>
#include <sys/stat.h>

#include "platform/utf8.h"
#include "platform/win32_errors.h"

namespace vkrt::platform {
namespace {

// Fills the six 'X' that end at `end` in `name` with random letters and digits; false when
// they are not there (EINVAL, as mkstemps says).
bool randomName(std::string& name, std::size_t end) {
  constexpr char kLetters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  if (end < 6 || end > name.size() || name.compare(end - 6, 6, "XXXXXX") != 0) {
    errno = EINVAL;
    return false;
  }
  static thread_local std::mt19937_64 random{std::random_device{}() ^
                                             static_cast<std::uint64_t>(::GetCurrentProcessId()) << 32 ^
                                             static_cast<std::uint64_t>(::GetTickCount64())};
  for (std::size_t i = end - 6; i < end; ++i) name[i] = kLetters[random() % (sizeof kLetters - 1)];
  return true;
}

constexpr int kNameTries = 100;

}  // namespace

int createTemporaryFile(std::string& pattern, std::size_t suffixLength) {
  const std::string original = pattern;
  for (int i = 0; i < kNameTries; ++i) {
    pattern = original;
    if (!randomName(pattern, pattern.size() - suffixLength)) return -1;
    int fd = -1;
    // _O_EXCL: CREATE_NEW, never an existing file.
    const errno_t e = ::_wsopen_s(&fd, wideFromUtf8(pattern).c_str(),
                                  _O_RDWR | _O_CREAT | _O_EXCL | _O_BINARY | _O_NOINHERIT, _SH_DENYNO,
                                  _S_IREAD | _S_IWRITE);
    if (e == 0) return fd;
    if (e != EEXIST) {
      errno = e;
      return -1;
    }
  }
  errno = EEXIST;
  return -1;
}

bool createTemporaryDirectory(std::string& pattern) {
  const std::string original = pattern;
  for (int i = 0; i < kNameTries; ++i) {
    pattern = original;
    if (!randomName(pattern, pattern.size())) return false;
    if (::_wmkdir(wideFromUtf8(pattern).c_str()) == 0) return true;
    if (errno != EEXIST) return false;
  }
  return false;
}

int makeDirectory(const std::string& path, unsigned) { return ::_wmkdir(wideFromUtf8(path).c_str()); }

int replaceFile(const std::string& from, const std::string& to) {
  const std::wstring source = wideFromUtf8(from), target = wideFromUtf8(to);
  // A program that has the target open without FILE_SHARE_DELETE (most viewers) makes the
  // move fail with ERROR_ACCESS_DENIED or ERROR_SHARING_VIOLATION until it lets go.
  constexpr auto kWait = std::chrono::seconds(2);
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    if (::MoveFileExW(source.c_str(), target.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) return 0;
    const DWORD error = ::GetLastError();
    // Held open, or refused for good: a read-only file, a folder, no target at all (then the
    // folder is what refuses).
    const DWORD attributes = ::GetFileAttributesW(target.c_str());
    const bool held = (error == ERROR_ACCESS_DENIED || error == ERROR_SHARING_VIOLATION ||
                       error == ERROR_LOCK_VIOLATION) &&
                      attributes != INVALID_FILE_ATTRIBUTES &&
                      (attributes & (FILE_ATTRIBUTE_READONLY | FILE_ATTRIBUTE_DIRECTORY)) == 0;
    if (!held) {
      errno = errnoFromWin32(error);
      return -1;
    }
    if (std::chrono::steady_clock::now() - start >= kWait) {
      errno = EBUSY;
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

int removeFile(const std::string& path) { return ::_wunlink(wideFromUtf8(path).c_str()); }

}  // namespace vkrt::platform
