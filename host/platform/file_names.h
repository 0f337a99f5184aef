// The names of files, on any system: where a symbolic link leads, and one name per file (the
// absolute path without links, '.' or '..') for telling files apart by name. Depends on nothing
// but the C++ library.
#pragma once

#include <optional>
#include <string>

namespace vkrt::platform {

// The text of the symbolic link `path` (readlink), or nothing with errno set (EINVAL: not a
// symbolic link).
std::optional<std::string> readSymbolicLink(const std::string& path);

// The absolute name of the existing file or folder `path`, every symbolic link, '.' and '..'
// resolved (realpath; Windows: GetFinalPathNameByHandleW, without its \\?\ prefix), or nothing
// with errno set (ENOENT...).
std::optional<std::string> realPath(const std::string& path);

// One name per file, whether it exists or not: realPath(path); else realPath of its folder and
// then its name; else realPath of the longest part of its absolute path that exists and the
// rest, lexically normal.
std::string canonicalName(const std::string& path);

}  // namespace vkrt::platform
