// inotify on the file's folder, filtered by the file's name.
#include "cli/file_watch.h"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "errors.h"
#include "interrupt.h"

namespace vkrt {

FileWatch::FileWatch(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  name_ = slash == std::string::npos ? path : path.substr(slash + 1);
  fd_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (fd_ < 0) throw IoError(std::string("cannot watch '") + path + "': " + std::strerror(errno));
  if (::inotify_add_watch(fd_, folder.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO | IN_ATTRIB) < 0) {
    const int e = errno;
    ::close(fd_);
    throw IoError("cannot watch the folder '" + folder + "' of '" + path + "': " + std::strerror(e));
  }
}

FileWatch::~FileWatch() {
  if (fd_ >= 0) ::close(fd_);
}

bool FileWatch::drainEvents() {
  alignas(inotify_event) char buffer[8192];
  bool named = false;
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n <= 0) return named;   // EAGAIN: nothing more (or an error, seen at the next poll)
    for (ssize_t at = 0; at < n;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      if (event->len > 0 && name_ == event->name) named = true;
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
    }
  }
}

bool FileWatch::waitForChange(int timeoutMs) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::milliseconds(timeoutMs < 0 ? 0 : timeoutMs);
  bool changed = false;
  for (;;) {
    throwIfInterrupted();
    int wait = changed ? kSettleMs : timeoutMs < 0 ? 1000 : 0;
    if (!changed && timeoutMs > 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      wait = static_cast<int>(std::max<long long>(0, std::min<long long>(left, 1000)));
    }
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, wait);
    if (ready < 0 && errno != EINTR) throw IoError(std::string("cannot wait for a change: ") + std::strerror(errno));
    if (ready > 0) {
      changed = drainEvents() || changed;
      continue;   // settle: wait again until a quiet kSettleMs
    }
    if (ready == 0 && changed) return true;                             // settled
    if (ready == 0 && timeoutMs >= 0 && Clock::now() >= deadline) return false;
  }
}

}  // namespace vkrt
