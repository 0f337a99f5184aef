// Signal handling for a clean stop (see interrupt.h). Only async-signal-safe calls in the
// handler: an atomic store, unlink and _exit.
#include "util/interrupt.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <mutex>
#include <thread>

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
  // No SA_RESTART: a read that waits (a FIFO) returns EINTR, and the reader stops.
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    // A signal ignored when vkrt started stays ignored (nohup, a background job's SIGINT).
    if (::sigaction(signal, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(signal, &action, nullptr);
  }
  // A write past the file-size limit (`ulimit -f`, as a batch job may set) fails with EFBIG
  // instead of the signal ending the process: the write's own error path then removes its
  // temporary file and says why.
  ::signal(SIGXFSZ, SIG_IGN);
}

int pendingInterrupt() { return received.load(std::memory_order_relaxed); }

void throwIfInterrupted() {
  if (int s = pendingInterrupt()) throw Interrupted(s);
}

void waitForSignalIfTesting(const char* stage) {
  static const char* const wanted = std::getenv("VKRT_TEST_WAIT_FOR_SIGNAL");
  if (!wanted || std::strcmp(wanted, stage) != 0) return;
  static std::once_flag announced;
  std::call_once(announced,
                 [stage] { std::fprintf(stderr, "vkrt: test hook: waiting for a signal during the %s\n", stage); });
  const auto giveUp = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (pendingInterrupt() == 0 && std::chrono::steady_clock::now() < giveUp)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void registerTemporaryFile(const char* path) { temporaryFile.store(path); }

}  // namespace vkrt
