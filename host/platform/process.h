// What the system says about this process and machine: memory, limits, its environment.
#pragma once

#include <string>

namespace vkrt::platform {

// The memory the machine has available now, in bytes (Linux: MemAvailable of /proc/meminfo;
// Windows: the available physical memory), or 0 when it cannot tell.
unsigned long long availableMemoryBytes();

// "; this process may use at most N MB of WHAT" for each limit set on this process's memory
// (POSIX: ulimit -v and -d; Windows: a job object's limit), or "".
std::string memoryLimitText();

// The folder of the user's caches (UTF-8): POSIX, $XDG_CACHE_HOME when it is absolute, else
// $HOME/.cache; Windows, %LOCALAPPDATA%. "" when there is none.
std::string userCacheFolder();

// Sets the environment variable `name` to `value` unless it is set already.
void setEnvironmentDefault(const std::string& name, const std::string& value);

// Whether the machine has a DRM render node (/dev/dri/renderD*), through which most Linux GPU
// drivers reach their GPU, or may have one (a /dev/dri that cannot be read). Windows' and
// macOS' drivers need none: true there, so that no driver is skipped.
bool hasDrmRenderNode();

}  // namespace vkrt::platform
