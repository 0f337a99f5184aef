// What an errno value means on POSIX: strerror's words (error_text.h).
#include "platform/error_text.h"

#include <cstring>

namespace vkrt::platform {

std::string errorText(int error) { return std::strerror(error); }

}  // namespace vkrt::platform
