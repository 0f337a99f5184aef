// The process and machine on Windows (process.h).
#define WIN32_LEAN_AND_MEAN
#define NOMINMAX
#include <windows.h>

#include <cstdlib>

#include "platform/process.h"
#include "platform/utf8.h"

namespace vkrt::platform {

unsigned long long availableMemoryBytes() {
  MEMORYSTATUSEX status{};
  status.dwLength = sizeof status;
  return ::GlobalMemoryStatusEx(&status) ? status.ullAvailPhys : 0;
}

std::string memoryLimitText() {
  JOBOBJECT_EXTENDED_LIMIT_INFORMATION job{};
  if (!::QueryInformationJobObject(nullptr, JobObjectExtendedLimitInformation, &job, sizeof job, nullptr)) return "";
  const DWORD flags = job.BasicLimitInformation.LimitFlags;
  if (flags & JOB_OBJECT_LIMIT_PROCESS_MEMORY)
    return "; this process may use at most " + std::to_string(job.ProcessMemoryLimit >> 20) +
           " MB of memory (its job object's limit)";
  if (flags & JOB_OBJECT_LIMIT_JOB_MEMORY)
    return "; this process's job may use at most " + std::to_string(job.JobMemoryLimit >> 20) + " MB of memory";
  return "";
}

std::string userCacheFolder() {
  const wchar_t* local = ::_wgetenv(L"LOCALAPPDATA");
  return local ? utf8FromWide(local) : "";
}

void setEnvironmentDefault(const std::string& name, const std::string& value) {
  const std::wstring wideName = wideFromUtf8(name);
  if (::GetEnvironmentVariableW(wideName.c_str(), nullptr, 0) > 0) return;
  ::SetEnvironmentVariableW(wideName.c_str(), wideFromUtf8(value).c_str());
  ::_putenv_s(name.c_str(), value.c_str());   // the C runtime's copy too (getenv)
}

// Windows' drivers reach their GPUs without DRM: none needs skipping.
bool hasDrmRenderNode() { return true; }

}  // namespace vkrt::platform
