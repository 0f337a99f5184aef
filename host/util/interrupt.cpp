// A clean stop on the system's requests (see interrupt.h; platform/signals.h delivers them).
// Only async-signal-safe calls in the handler: an atomic exchange, removeFileNow and exitNow.
#include "util/interrupt.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <mutex>
#include <thread>

#include "platform/signals.h"

namespace vkrt {
namespace {

std::atomic<int> received{0};
std::atomic<const char*> temporaryFile{nullptr};
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<const char*>::is_always_lock_free);

void onSignal(int signal) {
  if (received.exchange(signal) != 0) {   // the second one: stop now
    if (const char* path = temporaryFile.load()) platform::removeFileNow(path);
    platform::exitNow(128 + signal);
  }
}

}  // namespace

void installInterruptHandlers() { platform::onStopRequests(onSignal); }

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
