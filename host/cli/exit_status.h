// The exit statuses of `vkrt`, one meaning each, and the one place that turns an error into
// its status and its message. Documented in `vkrt --help` and doc/usage.md.
#pragma once

#include <cstdio>
#include <exception>
#include <string>

namespace vkrt {

enum ExitStatus : int {
  kExitOk = 0,
  kExitUsage = 1,         // a bad command line
  kExitScene = 2,         // the scene file is wrong: doc/scene-format.md, "Warnings and errors"'s errors (with --strict, its warnings)
  kExitDevice = 3,        // the Vulkan backend cannot render here: no loader, driver or device, a failed
                          // call, or a scene beyond the backend's or the device's limits
  kExitIo = 4,            // a file cannot be read or written (the scene, an image, the output)
  kExitDiffers = 5,       // images differ beyond the thresholds (diff, --check, --compare)
  kExitOutOfMemory = 6,   // host or device memory ran out, or would have (found before allocating)
  kExitInternal = 70,     // a bug in vkrt (EX_SOFTWARE of sysexits.h)
  kExitSignalBase = 128,  // + N: stopped by signal N (Ctrl-C: 130, SIGTERM: 143)
};

struct ErrorContext {
  std::string scenePath;   // named in the message of an allocation failure
  bool quiet = false;      // leave a SceneError's warnings out (its errors are always printed)
};

// Prints the message of `error` (any exception) on `err` and returns its exit status.
int reportError(std::exception_ptr error, const ErrorContext& context, std::FILE* err);

// The same on stderr, and the text printed, for a report that shows it too (grade's page, vkrt
// view's).
int reportErrorKeepingText(std::exception_ptr error, const ErrorContext& context, std::string& text);

// The exception being handled, or Interrupted when a signal has been received: a signal
// that cuts a wait short (an image read from a FIFO: "Interrupted system call") is what
// stopped the command, and its status is the signal's. Call it inside a catch block.
std::exception_ptr currentFailure();

// What a status means, in two or three words ("scene error", "stopped by signal 2").
std::string exitStatusName(int status);

// The status of a run of several scenes: the highest of theirs. By the table above that puts
// a signal over a bug over memory over I/O over the device over the scene over the command
// line, and any failure over success.
inline int worseExitStatus(int a, int b) { return a > b ? a : b; }

}  // namespace vkrt
