// The operating system's requests to stop: Ctrl-C, a terminal or console closed, a polite
// kill. POSIX: SIGINT, SIGHUP and SIGTERM. Windows: the console's control events (Ctrl-C and
// Ctrl-Break as SIGINT, a closed console, a log-off or shutdown as SIGHUP), so that both
// systems give the same exit status (128 + the number). util/interrupt.h decides what a
// request does; this file only delivers it.
#pragma once

namespace vkrt::platform {

// The numbers the requests are delivered as (the same on both systems).
inline constexpr int kSignalHangUp = 1;
inline constexpr int kSignalInterrupt = 2;
inline constexpr int kSignalTerminate = 15;

// Calls `onRequest(number)` for each request to stop. POSIX: from a signal handler (so
// `onRequest` may use only async-signal-safe calls: atomics, removeFileNow, exitNow); a
// signal ignored when the process started (nohup) stays ignored, and SIGXFSZ is ignored (a
// write past `ulimit -f` fails with an error instead of ending the process). Windows: from
// the console's handler thread; for a closed console, which Windows ends 5 s after the
// handler returns, the handler waits up to 4 s for the process to finish on its own.
void onStopRequests(void (*onRequest)(int number));

// Removes the file `path` (UTF-8) from a handler: no allocation on POSIX.
void removeFileNow(const char* path);

// Ends the process with `status` at once, no destructors, no buffers flushed.
[[noreturn]] void exitNow(int status);

}  // namespace vkrt::platform
