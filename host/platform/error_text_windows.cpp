// What an errno value means on Windows (error_text.h): the C runtime's words, but for a file
// that another program holds open, which Windows does not let vkrt replace.
#include "platform/error_text.h"

#include <cerrno>
#include <cstring>

namespace vkrt::platform {

std::string errorText(int error) {
  if (error == EBUSY)
    return "another program has the file open (an image viewer?), and Windows does not let it be replaced "
           "while it is; close it there and try again";
  return std::strerror(error);
}

}  // namespace vkrt::platform
