// Where symbolic links lead on POSIX: readlink, realpath (file_names.h).
#include "platform/file_names.h"

#include <climits>
#include <cstdlib>
#include <memory>

#include <unistd.h>

namespace vkrt::platform {

std::optional<std::string> readSymbolicLink(const std::string& path) {
  std::string text(PATH_MAX, '\0');
  for (;;) {
    const ssize_t n = ::readlink(path.c_str(), text.data(), text.size());
    if (n < 0) return std::nullopt;
    if (static_cast<std::size_t>(n) < text.size()) {
      text.resize(static_cast<std::size_t>(n));
      return text;
    }
    text.resize(text.size() * 2);   // perhaps cut short: again with room to spare
  }
}

std::optional<std::string> realPath(const std::string& path) {
  std::unique_ptr<char, decltype(&std::free)> real(::realpath(path.c_str(), nullptr), &std::free);
  if (!real) return std::nullopt;
  return std::string(real.get());
}

}  // namespace vkrt::platform
