// Errors of the environment and of vkrt's own code, shared by every stage. Each kind has one
// exit status (host/cli/exit_status.h). Depends on nothing.
#pragma once

#include <stdexcept>
#include <string>

namespace vkrt {

// A bad command line (or a request that cannot be met as given, such as a --scale that
// makes the image larger than the largest size): exit status 1.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file could not be read or written: the scene file, an image to compare, the output.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Memory ran out, or would: host or device memory, found before allocating (an image larger
// than the memory available) or when an allocation failed. The message says what needed it.
class OutOfMemory : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A bug in vkrt: one of its own invariants does not hold. Never the way to report bad input
// or a failing environment.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace vkrt
