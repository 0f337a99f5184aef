// Waiting for a file to change. The system's notices for the folder that holds it (and, for
// a symbolic link, the folder of the file it leads to: platform/file_watcher.h), so that an
// editor that saves by writing a new file and renaming it over the old one is seen as well as
// one that writes in place; and, as a backstop for what those watches miss (a write through a
// link whose target moved, the folder removed and made again, the file deleted), the file's
// identity through links (device, inode, size, times), compared at every wake-up.
#pragma once

#include <string>

#include "platform/file_watcher.h"

namespace vkrt {

class FileWatch {
 public:
  // Throws IoError when the folder of `path` cannot be watched.
  explicit FileWatch(const std::string& path);
  FileWatch(const FileWatch&) = delete;
  FileWatch& operator=(const FileWatch&) = delete;

  // Waits at most `timeoutMs` milliseconds (-1: no limit; 0: only looks) for the file to be
  // closed after writing, renamed into place, touched, replaced or deleted (Linux's notices
  // come once the file is whole; its identity is compared at least every kPollMs while
  // waiting), then for it to settle (no further notice for kSettleMs), and says whether it
  // changed (for a change only the identity shows, or one announced while the file is being
  // written, as Windows does: no further notice for kIdentitySettleMs).
  // Throws Interrupted when a signal arrives (interrupt.h).
  bool waitForChange(int timeoutMs);

  // An editor's save can be several such events (vim: write a copy, rename, set attributes):
  // the render waits until the file has been quiet this long.
  static constexpr int kSettleMs = 10;
  // How often the file's identity is compared while nothing else wakes the wait, and how long
  // a change seen that way (or announced as partial) must keep the new identity (a write in
  // place changes it as it goes).
  static constexpr int kPollMs = 500;
  static constexpr int kIdentitySettleMs = 100;

 private:
  std::string path_;
  platform::FileWatcher watcher_;
  std::string identity_;
};

}  // namespace vkrt
