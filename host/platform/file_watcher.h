// Events that may mean a file has changed: the system's notices for the folder that holds it
// (and, for a symbolic link, the folder of the file it leads to), filtered by the file's
// name, so that an editor that saves by writing a new file and renaming it over the old one
// is seen as well as one that writes in place; and the file's identity (its device and
// inode, size and times, through links), which the caller compares to see what the notices
// miss. What a change is, and when it has settled, is the caller's (watch/file_watch.h).
//
// Linux: inotify, whose IN_CLOSE_WRITE comes once a writer has closed the file: a change it
// names is whole. Windows: ReadDirectoryChangesW on the folder; there is no IN_CLOSE_WRITE,
// and a write is announced while it goes on (FILE_ACTION_MODIFIED, and a new file's
// FILE_ACTION_ADDED): those are Partial, and the caller waits until they stop coming and the
// identity stays the same; a rename into place or a deletion is whole. A link's target's
// folder is not watched there (the identity follows the link). Other POSIX systems (macOS,
// until it gets FSEvents or kqueue here): no notices at all, the identity alone.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace vkrt::platform {

// A watch that could not start, or a wait that failed: what() is the system's words;
// folder() the folder whose watch could not be made ("" when it was not a folder's).
class WatchError : public std::runtime_error {
 public:
  WatchError(std::string folder, const std::string& words) : std::runtime_error(words), folder_(std::move(folder)) {}
  const std::string& folder() const { return folder_; }

 private:
  std::string folder_;
};

class FileWatcher {
 public:
  // Watches the folder of `path` (and of its link's target). Throws WatchError when the
  // watching cannot start or the path's own folder cannot be watched.
  explicit FileWatcher(const std::string& path);
  ~FileWatcher();
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;

  enum class Seen {
    Nothing,       // the time ran out: nothing came
    OtherFiles,    // notices, none of them naming the file
    Whole,         // the file was written and closed, renamed into place, touched or deleted
    Partial,       // the file is being written (Windows): more may come
    Interrupted,   // a signal came (POSIX)
  };
  // Waits at most `timeoutMs` (0: only looks) for notices, and reads all that have come.
  // Throws WatchError when waiting fails.
  Seen wait(int timeoutMs);

  // Makes the watches again: the file's folder may have been made again, or its link lead
  // elsewhere now. A folder that does not exist (now) is left out.
  void rewatch();

  // The file's identity now, as text to compare ("" when it cannot be had: missing, or a
  // link that leads nowhere).
  std::string identity() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace vkrt::platform
