// Writing a file whole or not at all (temporary file beside the target, then rename), for
// every image format. Depends on nothing but errors.h and interrupt.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace vkrt {

// Throws IoError unless `path` can be created or replaced: its directory exists and is
// writable, and `path` itself is not a directory.
void checkOutputWritable(const std::string& path);

// Calls `write(fd)` on a temporary file beside `path` (named .vkrt-XXXXXX`suffix`), then
// renames it over `path`, so an existing file is replaced whole or not at all. Throws
// IoError (and whatever `write` throws, e.g. Interrupted); no temporary file is left behind.
void writeFileAtomic(const std::string& path, const char* suffix, const std::function<void(int fd)>& write);

// Writes all of `data` to `fd`, or throws IoError naming `path`.
void writeAll(int fd, const std::uint8_t* data, std::size_t size, const std::string& path);

}  // namespace vkrt
