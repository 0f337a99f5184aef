// Libraries opened at run time on Windows: LoadLibrary (library.h).
#define WIN32_LEAN_AND_MEAN
#define NOMINMAX
#include <windows.h>

#include "platform/library.h"

namespace vkrt::platform {

const char* vulkanLoaderName() { return "vulkan-1.dll"; }

void* openVulkanLoader() {
  // From the system's folders only (the GPU driver installs it there), not the current one.
  return reinterpret_cast<void*>(::LoadLibraryExW(L"vulkan-1.dll", nullptr, LOAD_LIBRARY_SEARCH_DEFAULT_DIRS));
}

void* librarySymbol(void* library, const char* name) {
  return reinterpret_cast<void*>(::GetProcAddress(static_cast<HMODULE>(library), name));
}

void pinLoadedLibraries() {}

}  // namespace vkrt::platform
