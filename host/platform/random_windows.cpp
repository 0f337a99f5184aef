// random.h on Windows: BCryptGenRandom with the system's preferred generator (bcrypt.dll).
#include "platform/random.h"

#ifndef WIN32_LEAN_AND_MEAN
#  define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX
#  define NOMINMAX
#endif
#include <windows.h>
#include <bcrypt.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace vkrt::platform {

void randomBytes(void* out, std::size_t size) {
  auto* bytes = static_cast<unsigned char*>(out);
  for (std::size_t got = 0; got < size;) {
    const auto n = static_cast<ULONG>(std::min<std::size_t>(size - got, 1u << 30));
    const NTSTATUS status = ::BCryptGenRandom(nullptr, bytes + got, n, BCRYPT_USE_SYSTEM_PREFERRED_RNG);
    if (status < 0) {   // !NT_SUCCESS
      char text[64];
      std::snprintf(text, sizeof text, "BCryptGenRandom: status 0x%08lx", static_cast<unsigned long>(status));
      throw std::runtime_error(text);
    }
    got += n;
  }
}

}  // namespace vkrt::platform
