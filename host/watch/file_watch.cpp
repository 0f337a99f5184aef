// inotify on the file's folder (and its target's), filtered by the file's name, with stat()
// as the backstop.
#include "watch/file_watch.h"

#include <poll.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "util/errors.h"
#include "util/interrupt.h"

namespace vkrt {
namespace {

// The folder and name of `path`.
std::pair<std::string, std::string> split(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return {".", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

}  // namespace

FileWatch::FileWatch(const std::string& path) : path_(path) {
  fd_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (fd_ < 0) throw IoError(std::string("cannot watch '") + path + "': " + std::strerror(errno));
  if (const int e = watchFolders(); e != 0) {
    ::close(fd_);
    throw IoError("cannot watch the folder '" + split(path).first + "' of '" + path + "': " + std::strerror(e));
  }
  identity_ = identity();
}

FileWatch::~FileWatch() {
  if (fd_ >= 0) ::close(fd_);
}

int FileWatch::watchFolders() {
  for (const Watched& w : watched_) ::inotify_rm_watch(fd_, w.wd);   // a watch of a removed folder is gone already
  watched_.clear();
  std::vector<std::string> paths = {path_};
  std::unique_ptr<char, decltype(&std::free)> target(::realpath(path_.c_str(), nullptr), &std::free);
  if (target && split(target.get()) != split(path_)) paths.push_back(target.get());
  int pathFolderError = 0;
  for (const std::string& p : paths) {
    auto [folder, name] = split(p);
    const int wd = ::inotify_add_watch(fd_, folder.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO | IN_ATTRIB | IN_DELETE);
    if (wd >= 0) watched_.push_back({wd, name});
    else if (&p == &paths.front()) pathFolderError = errno;
  }
  return pathFolderError;
}

std::string FileWatch::identity() const {
  struct stat st {};
  if (::stat(path_.c_str(), &st) != 0) return "";
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" +
         std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec) + ":" +
         std::to_string(st.st_ctim.tv_sec) + "." + std::to_string(st.st_ctim.tv_nsec);
}

bool FileWatch::drainEvents() {
  alignas(inotify_event) char buffer[8192];
  bool named = false;
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n <= 0) return named;   // EAGAIN: nothing more (or an error, seen at the next poll)
    for (ssize_t at = 0; at < n;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      if (event->len > 0)
        named = named || std::any_of(watched_.begin(), watched_.end(), [&](const Watched& w) {
                  return w.wd == event->wd && w.name == event->name;
                });
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
    }
  }
}

bool FileWatch::waitForChange(int timeoutMs) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::milliseconds(timeoutMs < 0 ? 0 : timeoutMs);
  bool changed = false;
  auto lastChange = Clock::now();
  int settleMs = kSettleMs;
  for (;;) {
    throwIfInterrupted();
    int wait = changed ? kSettleMs : timeoutMs < 0 ? kPollMs : 0;
    if (!changed && timeoutMs > 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      wait = static_cast<int>(std::max<long long>(0, std::min<long long>(left, kPollMs)));
    }
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, wait);
    if (ready < 0 && errno != EINTR) throw IoError(std::string("cannot wait for a change: ") + std::strerror(errno));
    if (ready > 0) {
      if (drainEvents()) {
        changed = true;
        lastChange = Clock::now();
      }
      continue;   // settle: wait again until a quiet kSettleMs
    }
    if (ready < 0) continue;
    // What the watches missed: the file is another one, written, gone, or back. Seen this way
    // it may be in the middle of a write, so it must keep its identity kIdentitySettleMs.
    std::string now = identity();
    if (now != identity_) {
      identity_ = std::move(now);
      watchFolders();   // a new folder, or a link that leads elsewhere now
      // A change the events announced (a file renamed over the scene has a new identity too)
      // is whole already: only one seen by its identity alone must keep it a while.
      if (!changed) {
        changed = true;
        lastChange = Clock::now();
        settleMs = kIdentitySettleMs;
      }
      continue;
    }
    if (changed && Clock::now() - lastChange >= std::chrono::milliseconds(settleMs)) {   // settled
      identity_ = identity();   // what the events announced, so that it is not seen twice
      return true;
    }
    if (!changed && timeoutMs >= 0 && Clock::now() >= deadline) return false;
  }
}

}  // namespace vkrt
