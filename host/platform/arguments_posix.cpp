// The command line on POSIX: argv as it is (arguments.h).
#include "platform/arguments.h"

namespace vkrt::platform {

std::vector<std::string> commandLineArguments(int argc, char** argv) {
  return std::vector<std::string>(argv + (argc > 0 ? 1 : 0), argv + argc);
}

}  // namespace vkrt::platform
