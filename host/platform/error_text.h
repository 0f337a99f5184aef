// What an errno value means, in words for a message, on any system. Depends on nothing but the
// C++ library.
#pragma once

#include <string>

namespace vkrt::platform {

// std::strerror's words for `error`; on Windows EBUSY from replaceFile (file_changes.h) says
// that another program holds the file open.
std::string errorText(int error);

}  // namespace vkrt::platform
