// What socket.h's types do the same way on every system.
#include "platform/socket.h"

namespace vkrt::platform {

bool Transfer::wouldBlock() const { return failed() && isWouldBlock(error); }

Socket& Socket::operator=(Socket&& other) noexcept {
  if (this != &other) {
    close();
    handle_ = other.release();
  }
  return *this;
}

}  // namespace vkrt::platform
