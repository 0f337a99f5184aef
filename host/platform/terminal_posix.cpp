// The terminal on POSIX: isatty (terminal.h).
#include "platform/terminal.h"

#include <unistd.h>

namespace vkrt::platform {

bool isTerminal(std::FILE* stream) { return ::isatty(::fileno(stream)) != 0; }

void prepareStandardStreams() {}   // stderr is unbuffered already (C's rule)

}  // namespace vkrt::platform
