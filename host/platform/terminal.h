// The terminal: whether a stream goes to one (progress bars are drawn only there).
#pragma once

#include <cstdio>

namespace vkrt::platform {

// Whether `stream` (stdout or stderr) writes to a terminal or console that shows the escape
// sequences vkrt draws with ("\r", "\033[K"). Windows: a console, whose escape processing
// this turns on.
bool isTerminal(std::FILE* stream);

}  // namespace vkrt::platform
