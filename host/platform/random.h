// Random bytes from the operating system's source, fit for secrets (vkrt view's token).
#pragma once

#include <cstddef>

namespace vkrt::platform {

// Fills `size` bytes at `out`: getrandom on Linux (getentropy on other POSIX systems),
// BCryptGenRandom with the system's preferred generator on Windows. Throws
// std::runtime_error, its what() the call's name and the system's words
// ("getrandom: Function not implemented").
void randomBytes(void* out, std::size_t size);

}  // namespace vkrt::platform
