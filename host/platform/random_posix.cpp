// random.h on POSIX: getrandom (Linux), getentropy (macOS and the BSDs: at most 256 bytes a call).
#include "platform/random.h"

#ifdef __linux__
#  include <sys/random.h>
#else
#  include <unistd.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace vkrt::platform {

void randomBytes(void* out, std::size_t size) {
  auto* bytes = static_cast<unsigned char*>(out);
  std::size_t got = 0;
  while (got < size) {
#ifdef __linux__
    const ssize_t n = ::getrandom(bytes + got, size - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(std::string("getrandom: ") + std::strerror(errno));
    got += static_cast<std::size_t>(n);
#else
    const std::size_t n = std::min<std::size_t>(size - got, 256);
    if (::getentropy(bytes + got, n) != 0) throw std::runtime_error(std::string("getentropy: ") + std::strerror(errno));
    got += n;
#endif
  }
}

}  // namespace vkrt::platform
