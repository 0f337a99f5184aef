// The command line's arguments, as UTF-8, and the console's text: POSIX passes them as they
// are; Windows' `argv` is in the process's code page, so they are taken from the wide command
// line, and the console is told to show UTF-8.
#pragma once

#include <string>
#include <vector>

namespace vkrt::platform {

// argv[1..argc-1] as UTF-8. Windows: also sets the console's output code page to UTF-8, so
// that messages naming non-ASCII files show them as they are.
std::vector<std::string> commandLineArguments(int argc, char** argv);

}  // namespace vkrt::platform
