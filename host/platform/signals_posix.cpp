// Stop requests on POSIX: sigaction (signals.h).
#include "platform/signals.h"

#include <initializer_list>

#include <signal.h>
#include <unistd.h>

namespace vkrt::platform {
namespace {

void (*handler)(int) = nullptr;

void onSignal(int number) { handler(number); }

}  // namespace

void onStopRequests(void (*onRequest)(int number)) {
  handler = onRequest;
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
  static_assert(SIGHUP == kSignalHangUp && SIGINT == kSignalInterrupt && SIGTERM == kSignalTerminate);
  // A write past the file-size limit (`ulimit -f`, as a batch job may set) fails with EFBIG
  // instead of the signal ending the process: the write's own error path then removes its
  // temporary file and says why.
  ::signal(SIGXFSZ, SIG_IGN);
}

void removeFileNow(const char* path) { ::unlink(path); }

void exitNow(int status) { ::_exit(status); }

}  // namespace vkrt::platform
