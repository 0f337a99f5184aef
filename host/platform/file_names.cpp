// One name per file, on every system (file_names.h).
#include "platform/file_names.h"

#include <filesystem>
#include <system_error>

namespace vkrt::platform {

std::string canonicalName(const std::string& path) {
  namespace fs = std::filesystem;
  if (std::optional<std::string> real = realPath(path)) return *real;
  const fs::path p(path);
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  if (std::optional<std::string> realDir = realPath(dir.string())) return (fs::path(*realDir) / p.filename()).string();
  // Neither is there: the longest part that is, and the rest as written.
  std::error_code ec;
  const fs::path absolute = fs::absolute(p, ec);
  if (ec) return p.lexically_normal().string();
  fs::path prefix, rest;
  for (const fs::path& part : absolute) {
    if (rest.empty() && realPath((prefix / part).string()))
      prefix /= part;
    else
      rest /= part;
  }
  const std::optional<std::string> realPrefix = prefix.empty() ? std::nullopt : realPath(prefix.string());
  return ((realPrefix ? fs::path(*realPrefix) : prefix) / rest).lexically_normal().string();
}

}  // namespace vkrt::platform
