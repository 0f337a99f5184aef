// Signal handling for a clean stop (see interrupt.h). Only async-signal-safe calls in the
// handler: an atomic store, unlink and _exit.
#include "interrupt.h"

#include <csignal>

#include <unistd.h>

namespace vkrt {
namespace {

std::atomic<int> received{0};
std::atomic<const char*> temporaryFile{nullptr};
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<const char*>::is_always_lock_free);

void onSignal(int signal) {
  if (received.exchange(signal) != 0) {   // the second one: stop now
    if (const char* path = temporaryFile.load()) ::unlink(path);
    ::_exit(128 + signal);
  }
}

}  // namespace

void installInterruptHandlers() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

int pendingInterrupt() { return received.load(std::memory_order_relaxed); }

void throwIfInterrupted() {
  if (int s = pendingInterrupt()) throw Interrupted(s);
}

void registerTemporaryFile(const char* path) { temporaryFile.store(path); }

}  // namespace vkrt
