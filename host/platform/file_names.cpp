// One name per file, on every system (file_names.h).
#include "platform/file_names.h"

#include <filesystem>
#include <system_error>

#include "platform/path_text.h"

namespace vkrt::platform {

std::string canonicalName(const std::string& path) {
  namespace fs = std::filesystem;
  if (std::optional<std::string> real = realPath(path)) return *real;
  const fs::path p = pathFromUtf8(path);
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  if (std::optional<std::string> realDir = realPath(utf8FromPath(dir)))
    return utf8FromPath(pathFromUtf8(*realDir) / p.filename());
  // Neither is there: the longest part that is, and the rest as written.
  std::error_code ec;
  const fs::path absolute = fs::absolute(p, ec);
  if (ec) return utf8FromPath(p.lexically_normal());
  fs::path prefix, rest;
  for (const fs::path& part : absolute) {
    if (rest.empty() && realPath(utf8FromPath(prefix / part)))
      prefix /= part;
    else
      rest /= part;
  }
  const std::optional<std::string> realPrefix = prefix.empty() ? std::nullopt : realPath(utf8FromPath(prefix));
  return utf8FromPath(((realPrefix ? pathFromUtf8(*realPrefix) : prefix) / rest).lexically_normal());
}

}  // namespace vkrt::platform
