// Paths and UTF-8 names on POSIX (path_text.h): a path is its bytes, so nothing changes.
#include "platform/path_text.h"

namespace vkrt::platform {

std::filesystem::path pathFromUtf8(const std::string& text) { return std::filesystem::path(text); }

std::string utf8FromPath(const std::filesystem::path& path) { return path.native(); }

}  // namespace vkrt::platform
