// Ctrl-C (SIGINT), SIGTERM and SIGHUP: the first one asks the command to stop at the next
// tile, band, image row or read of the scene file, or before the written file replaces the
// old one (Interrupted is thrown, the temporary output file removed, an existing output left
// as it was); a second one ends the process at once, still removing the temporary file.
#pragma once

#include <atomic>
#include <stdexcept>

namespace vkrt {

class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal) : std::runtime_error("interrupted"), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

// Installs the handlers for SIGINT, SIGTERM and SIGHUP, except for a signal ignored when the
// process started (nohup), and ignores SIGXFSZ (a write past `ulimit -f` then fails with an
// error): vkrt's main does, before any command; a library user need not.
void installInterruptHandlers();

// The signal received so far, or 0. Safe to poll from any thread.
int pendingInterrupt();

// Throws Interrupted when a signal has been received.
void throwIfInterrupted();

// For the tests of interruption only: when the environment variable VKRT_TEST_WAIT_FOR_SIGNAL
// equals `stage` ("render" or "write"), says so on stderr once ("vkrt: test hook: waiting for
// a signal during the STAGE") and waits until a signal has been received (at most a minute),
// so that a test's signal arrives at that point whatever the machine's speed. Otherwise it
// returns at once.
void waitForSignalIfTesting(const char* stage);

// The temporary file being written (or nullptr): the second signal removes it before exiting.
// The string must outlive the registration.
void registerTemporaryFile(const char* path);

}  // namespace vkrt
