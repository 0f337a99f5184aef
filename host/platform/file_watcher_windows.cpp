// file_watcher.h on Windows: ReadDirectoryChangesW on the file's folder (overlapped, waited
// on with its event), and the identity from an open handle (volume serial and file index,
// size, write and change times). A change notice comes while a write goes on, not once the
// writer has closed the file (Windows has no IN_CLOSE_WRITE): FILE_ACTION_MODIFIED and
// FILE_ACTION_ADDED are Partial, and the caller waits for them to stop.
#include "platform/file_watcher.h"

#ifndef WIN32_LEAN_AND_MEAN
#  define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX
#  define NOMINMAX
#endif
#include <windows.h>

#include <utility>
#include <vector>

#include "platform/error_text.h"
#include "platform/utf8.h"
#include "platform/win32_errors.h"

namespace vkrt::platform {
namespace {

std::string lastErrorWords() { return errorText(errnoFromWin32(::GetLastError())); }

// The folder and name of `path`: either separator; a drive's root ("C:\") stays a root.
std::pair<std::string, std::string> split(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  if (slash == std::string::npos) {
    if (path.size() >= 2 && path[1] == ':') return {path.substr(0, 2), path.substr(2)};   // "C:name"
    return {".", path};
  }
  const bool root = slash == 0 || (slash == 2 && path[1] == ':');
  return {path.substr(0, root ? slash + 1 : slash), path.substr(slash + 1)};
}

// One folder's notices: its handle, the read in flight, and what it fills.
struct Folder {
  HANDLE handle = INVALID_HANDLE_VALUE;
  OVERLAPPED overlapped{};
  std::vector<DWORD> buffer = std::vector<DWORD>(16384 / sizeof(DWORD));   // DWORD-aligned, as it must be
  std::wstring name;   // the file's name in it

  ~Folder() {
    if (handle != INVALID_HANDLE_VALUE) {
      ::CancelIoEx(handle, &overlapped);
      DWORD ignored = 0;
      ::GetOverlappedResult(handle, &overlapped, &ignored, TRUE);   // the buffer is the system's until then
      ::CloseHandle(handle);
    }
    if (overlapped.hEvent) ::CloseHandle(overlapped.hEvent);
  }
  bool read() {
    constexpr DWORD kChanges = FILE_NOTIFY_CHANGE_FILE_NAME | FILE_NOTIFY_CHANGE_DIR_NAME | FILE_NOTIFY_CHANGE_SIZE |
                               FILE_NOTIFY_CHANGE_LAST_WRITE | FILE_NOTIFY_CHANGE_ATTRIBUTES |
                               FILE_NOTIFY_CHANGE_CREATION;
    return ::ReadDirectoryChangesW(handle, buffer.data(), static_cast<DWORD>(buffer.size() * sizeof(DWORD)), FALSE,
                                   kChanges, nullptr, &overlapped, nullptr) != 0;
  }
  bool names(const wchar_t* file, DWORD bytes) const {
    return ::CompareStringOrdinal(file, static_cast<int>(bytes / sizeof(wchar_t)), name.c_str(),
                                  static_cast<int>(name.size()), TRUE) == CSTR_EQUAL;
  }
};

}  // namespace

struct FileWatcher::State {
  std::string path;
  std::unique_ptr<Folder> folder;   // null: the folder is not there (now)

  // Opens the folder of the path and starts reading its notices: 0, or the errno of the failure.
  int watchFolder() {
    folder.reset();
    auto [name, file] = split(path);
    auto f = std::make_unique<Folder>();
    f->name = wideFromUtf8(file);
    f->handle = ::CreateFileW(wideFromUtf8(name).c_str(), FILE_LIST_DIRECTORY,
                              FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr, OPEN_EXISTING,
                              FILE_FLAG_BACKUP_SEMANTICS | FILE_FLAG_OVERLAPPED, nullptr);
    if (f->handle == INVALID_HANDLE_VALUE) return errnoFromWin32(::GetLastError());
    f->overlapped.hEvent = ::CreateEventW(nullptr, TRUE, FALSE, nullptr);
    if (!f->overlapped.hEvent || !f->read()) return errnoFromWin32(::GetLastError());
    folder = std::move(f);
    return 0;
  }
};

FileWatcher::FileWatcher(const std::string& path) : state_(std::make_unique<State>()) {
  state_->path = path;
  if (const int e = state_->watchFolder(); e != 0) throw WatchError(split(path).first, errorText(e));
}

FileWatcher::~FileWatcher() = default;

FileWatcher::Seen FileWatcher::wait(int timeoutMs) {
  Folder* f = state_->folder.get();
  if (!f) {   // nothing to wait on: the identity alone
    ::Sleep(static_cast<DWORD>(timeoutMs < 0 ? 0 : timeoutMs));
    return Seen::Nothing;
  }
  const DWORD waited = ::WaitForSingleObject(f->overlapped.hEvent, timeoutMs < 0 ? INFINITE : static_cast<DWORD>(timeoutMs));
  if (waited == WAIT_TIMEOUT) return Seen::Nothing;
  if (waited != WAIT_OBJECT_0) throw WatchError("", lastErrorWords());
  DWORD bytes = 0;
  Seen seen = Seen::OtherFiles;
  if (!::GetOverlappedResult(f->handle, &f->overlapped, &bytes, FALSE)) {
    state_->folder.reset();   // the folder went away: the identity sees what follows; rewatch() looks again
    return Seen::Partial;
  }
  if (bytes == 0) {
    seen = Seen::Partial;   // more notices than the buffer held: any of them may be the file's
  } else {
    const auto* at = reinterpret_cast<const unsigned char*>(f->buffer.data());
    for (;;) {
      const auto* notice = reinterpret_cast<const FILE_NOTIFY_INFORMATION*>(at);
      if (f->names(notice->FileName, notice->FileNameLength)) {
        const bool whole = notice->Action == FILE_ACTION_RENAMED_NEW_NAME || notice->Action == FILE_ACTION_REMOVED ||
                           notice->Action == FILE_ACTION_RENAMED_OLD_NAME;
        if (whole && seen != Seen::Partial) seen = Seen::Whole;
        else if (!whole) seen = Seen::Partial;
      }
      if (notice->NextEntryOffset == 0) break;
      at += notice->NextEntryOffset;
    }
  }
  ::ResetEvent(f->overlapped.hEvent);
  if (!f->read()) state_->folder.reset();
  return seen;
}

void FileWatcher::rewatch() { state_->watchFolder(); }

std::string FileWatcher::identity() const {
  // Through links, as stat() (no FILE_FLAG_OPEN_REPARSE_POINT); any sharing, so that no writer waits.
  const HANDLE h = ::CreateFileW(wideFromUtf8(state_->path).c_str(), FILE_READ_ATTRIBUTES,
                                 FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr, OPEN_EXISTING,
                                 FILE_FLAG_BACKUP_SEMANTICS, nullptr);
  if (h == INVALID_HANDLE_VALUE) return "";
  BY_HANDLE_FILE_INFORMATION info{};
  FILE_BASIC_INFO basic{};
  const bool known = ::GetFileInformationByHandle(h, &info) &&
                     ::GetFileInformationByHandleEx(h, FileBasicInfo, &basic, sizeof basic);
  ::CloseHandle(h);
  if (!known) return "";
  auto join = [](DWORD high, DWORD low) { return (static_cast<unsigned long long>(high) << 32) | low; };
  return std::to_string(info.dwVolumeSerialNumber) + ":" + std::to_string(join(info.nFileIndexHigh, info.nFileIndexLow)) +
         ":" + std::to_string(join(info.nFileSizeHigh, info.nFileSizeLow)) + ":" +
         std::to_string(basic.LastWriteTime.QuadPart) + ":" + std::to_string(basic.ChangeTime.QuadPart);
}

}  // namespace vkrt::platform
