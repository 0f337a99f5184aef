// The process and machine on POSIX (process.h).
#include "platform/process.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <system_error>
#include <utility>

#include <sys/resource.h>

namespace vkrt::platform {

unsigned long long availableMemoryBytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  unsigned long long kb = 0;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024ULL;
  return 0;
}

std::string memoryLimitText() {
  std::string s;
  for (auto [resource, name] : {std::pair{RLIMIT_AS, "address space: ulimit -v"}, std::pair{RLIMIT_DATA, "data: ulimit -d"}}) {
    struct rlimit limit {};
    if (::getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      s += "; this process may use at most " + std::to_string(static_cast<unsigned long long>(limit.rlim_cur) >> 20) +
           " MB of " + name;
  }
  return s;
}

std::string userCacheFolder() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && xdg[0] == '/') return xdg;
  const char* home = std::getenv("HOME");
  return home && home[0] != '\0' ? std::string(home) + "/.cache" : "";
}

void setEnvironmentDefault(const std::string& name, const std::string& value) {
  ::setenv(name.c_str(), value.c_str(), 0);
}

bool hasDrmRenderNode() {
#ifdef __linux__
  std::error_code ec;
  std::filesystem::directory_iterator it("/dev/dri", ec), end;
  if (ec) return ec != std::errc::no_such_file_or_directory;   // unreadable: assume there may be one
  for (; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind("renderD", 0) == 0) return true;
  return static_cast<bool>(ec);
#else
  return true;
#endif
}

}  // namespace vkrt::platform
