// Waiting for a file to change (inotify): the folder that holds it is watched, so that an
// editor that saves by writing a new file and renaming it over the old one is seen as well
// as one that writes in place.
#pragma once

#include <string>

namespace vkrt {

class FileWatch {
 public:
  // Throws IoError when the folder of `path` cannot be watched.
  explicit FileWatch(const std::string& path);
  ~FileWatch();
  FileWatch(const FileWatch&) = delete;
  FileWatch& operator=(const FileWatch&) = delete;

  // Waits at most `timeoutMs` milliseconds (-1: no limit; 0: only looks) for the file to be
  // closed after writing, renamed into place or touched (each an event that comes once the
  // file is whole), then for it to settle (no further change for kSettleMs), and says whether
  // it changed. Throws Interrupted when a signal arrives (interrupt.h).
  bool waitForChange(int timeoutMs);

  // An editor's save can be several such events (vim: write a copy, rename, set attributes):
  // the render waits until the file has been quiet this long.
  static constexpr int kSettleMs = 10;

 private:
  // Reads the pending events; true when one names the file.
  bool drainEvents();
  int fd_ = -1;
  std::string name_;   // the file's name in its folder
};

}  // namespace vkrt
