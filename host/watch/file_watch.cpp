// The settling of a file's changes, from the notices and identity of platform/file_watcher.h.
#include "watch/file_watch.h"

#include <algorithm>
#include <chrono>

#include "util/errors.h"
#include "util/interrupt.h"

namespace vkrt {
namespace {

// The watcher of `path`, its failure to start in vkrt's words.
platform::FileWatcher watcherOf(const std::string& path) {
  try {
    return platform::FileWatcher(path);
  } catch (const platform::WatchError& e) {
    if (e.folder().empty()) throw IoError("cannot watch '" + path + "': " + e.what());
    throw IoError("cannot watch the folder '" + e.folder() + "' of '" + path + "': " + e.what());
  }
}

}  // namespace

FileWatch::FileWatch(const std::string& path) : path_(path), watcher_(watcherOf(path)), identity_(watcher_.identity()) {}

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
    platform::FileWatcher::Seen seen;
    try {
      seen = watcher_.wait(wait);
    } catch (const platform::WatchError& e) {
      throw IoError(std::string("cannot wait for a change: ") + e.what());
    }
    using Seen = platform::FileWatcher::Seen;
    if (seen == Seen::Whole || seen == Seen::Partial) {
      changed = true;
      lastChange = Clock::now();
      if (seen == Seen::Partial) settleMs = kIdentitySettleMs;   // still being written, maybe
    }
    if (seen != Seen::Nothing) continue;   // settle: wait again until a quiet kSettleMs
    // What the watches missed: the file is another one, written, gone, or back. Seen this way
    // it may be in the middle of a write, so it must keep its identity kIdentitySettleMs.
    std::string now = watcher_.identity();
    if (now != identity_) {
      identity_ = std::move(now);
      watcher_.rewatch();   // a new folder, or a link that leads elsewhere now
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
      identity_ = watcher_.identity();   // what the notices announced, so that it is not seen twice
      return true;
    }
    if (!changed && timeoutMs >= 0 && Clock::now() >= deadline) return false;
  }
}

}  // namespace vkrt
