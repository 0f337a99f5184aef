// file_watcher.h on POSIX: inotify on Linux (the folders' watches, read through poll), and
// stat() for the identity; elsewhere no notices, the identity alone.
#include "platform/file_watcher.h"

#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>
#ifdef __linux__
#  include <sys/inotify.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

namespace vkrt::platform {
namespace {

// The folder and name of `path`.
std::pair<std::string, std::string> split(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return {".", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

}  // namespace

struct FileWatcher::State {
  struct Watched {
    int wd;
    std::string name;   // the file's name in that folder
  };
  std::string path;
  int fd = -1;
  std::vector<Watched> watched;

  // (Re)creates the watches: the folder of the path, and that of its target when the path is
  // a symbolic link. Returns the errno of the path's own folder's watch, 0 when it was made.
  int watchFolders() {
#ifdef __linux__
    for (const Watched& w : watched) ::inotify_rm_watch(fd, w.wd);   // a watch of a removed folder is gone already
    watched.clear();
    std::vector<std::string> paths = {path};
    std::unique_ptr<char, decltype(&std::free)> target(::realpath(path.c_str(), nullptr), &std::free);
    if (target && split(target.get()) != split(path)) paths.push_back(target.get());
    int pathFolderError = 0;
    for (const std::string& p : paths) {
      auto [folder, name] = split(p);
      const int wd = ::inotify_add_watch(fd, folder.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO | IN_ATTRIB | IN_DELETE);
      if (wd >= 0) watched.push_back({wd, name});
      else if (&p == &paths.front()) pathFolderError = errno;
    }
    return pathFolderError;
#else
    struct stat st {};
    return ::stat(split(path).first.c_str(), &st) == 0 ? 0 : errno;
#endif
  }

  // Reads the pending notices; true when one names the file.
  bool drainEvents() {
#ifdef __linux__
    alignas(inotify_event) char buffer[8192];
    bool named = false;
    for (;;) {
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n <= 0) return named;   // EAGAIN: nothing more (or an error, seen at the next poll)
      for (ssize_t at = 0; at < n;) {
        const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
        if (event->len > 0)
          named = named || std::any_of(watched.begin(), watched.end(), [&](const Watched& w) {
                    return w.wd == event->wd && w.name == event->name;
                  });
        at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
      }
    }
#else
    return false;
#endif
  }
};

FileWatcher::FileWatcher(const std::string& path) : state_(std::make_unique<State>()) {
  state_->path = path;
#ifdef __linux__
  state_->fd = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (state_->fd < 0) throw WatchError("", std::strerror(errno));
#endif
  if (const int e = state_->watchFolders(); e != 0) {
    if (state_->fd >= 0) ::close(state_->fd);
    throw WatchError(split(path).first, std::strerror(e));
  }
}

FileWatcher::~FileWatcher() {
  if (state_->fd >= 0) ::close(state_->fd);
}

FileWatcher::Seen FileWatcher::wait(int timeoutMs) {
  pollfd p{state_->fd, POLLIN, 0};   // (no descriptor off Linux: poll only sleeps)
  const int ready = ::poll(&p, state_->fd >= 0 ? 1 : 0, timeoutMs);
  if (ready < 0 && errno != EINTR) throw WatchError("", std::strerror(errno));
  if (ready < 0) return Seen::Interrupted;
  if (ready == 0) return Seen::Nothing;
  return state_->drainEvents() ? Seen::Whole : Seen::OtherFiles;
}

void FileWatcher::rewatch() { state_->watchFolders(); }

std::string FileWatcher::identity() const {
  struct stat st {};
  if (::stat(state_->path.c_str(), &st) != 0) return "";
#ifdef __APPLE__
  const timespec& modified = st.st_mtimespec;
  const timespec& changed = st.st_ctimespec;
#else
  const timespec& modified = st.st_mtim;
  const timespec& changed = st.st_ctim;
#endif
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" +
         std::to_string(modified.tv_sec) + "." + std::to_string(modified.tv_nsec) + ":" +
         std::to_string(changed.tv_sec) + "." + std::to_string(changed.tv_nsec);
}

}  // namespace vkrt::platform
