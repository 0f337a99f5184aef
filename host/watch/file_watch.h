// Waiting for a file to change. inotify on the folder that holds it (and, for a symbolic link,
// on the folder of the file it leads to), so that an editor that saves by writing a new file
// and renaming it over the old one is seen as well as one that writes in place; and, as a
// backstop for what those watches miss (a write through a link whose target moved, the
// folder removed and made again, the file deleted), the file's identity as stat() gives it
// through links (device, inode, size, times), compared at every wake-up.
#pragma once

#include <string>
#include <vector>

namespace vkrt {

class FileWatch {
 public:
  // Throws IoError when the folder of `path` cannot be watched.
  explicit FileWatch(const std::string& path);
  ~FileWatch();
  FileWatch(const FileWatch&) = delete;
  FileWatch& operator=(const FileWatch&) = delete;

  // Waits at most `timeoutMs` milliseconds (-1: no limit; 0: only looks) for the file to be
  // closed after writing, renamed into place, touched, replaced or deleted (inotify's events
  // come once the file is whole; its identity is compared at least every kPollMs while
  // waiting), then for it to settle (no further event for kSettleMs), and says whether it
  // changed (for a change only the identity shows, no further change for kIdentitySettleMs).
  // Throws Interrupted when a signal arrives (interrupt.h).
  bool waitForChange(int timeoutMs);

  // An editor's save can be several such events (vim: write a copy, rename, set attributes):
  // the render waits until the file has been quiet this long.
  static constexpr int kSettleMs = 10;
  // How often the file's identity is compared while nothing else wakes the wait, and how long
  // a change seen that way must keep the new identity (a write in place changes it as it goes).
  static constexpr int kPollMs = 500;
  static constexpr int kIdentitySettleMs = 100;

 private:
  struct Watched {
    int wd;
    std::string name;   // the file's name in that folder
  };
  // (Re)creates the inotify watches: the folder of the path, and that of its target when the
  // path is a symbolic link. A folder that does not exist (now) is left out: the identity
  // check sees the file come back, and the watches are made again then. Returns the errno of
  // the path's own folder's watch, 0 when it was made.
  int watchFolders();
  // Reads the pending events; true when one names the file.
  bool drainEvents();
  // The file's identity now ("" when stat() fails: missing, or a dangling link).
  std::string identity() const;

  std::string path_;
  int fd_ = -1;
  std::vector<Watched> watched_;
  std::string identity_;
};

}  // namespace vkrt
