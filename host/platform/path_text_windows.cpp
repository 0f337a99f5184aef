// Paths and UTF-8 names on Windows (path_text.h): a path holds UTF-16, converted by the same
// functions as every *W call of this layer (utf8.h), not by libstdc++'s std::string
// constructor, which reads each byte as one Latin-1 letter.
#include "platform/path_text.h"

#include "platform/utf8.h"

namespace vkrt::platform {

std::filesystem::path pathFromUtf8(const std::string& text) { return std::filesystem::path(wideFromUtf8(text)); }

std::string utf8FromPath(const std::filesystem::path& path) { return utf8FromWide(path.native()); }

}  // namespace vkrt::platform
